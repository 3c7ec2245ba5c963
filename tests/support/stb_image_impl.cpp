// stb_image, the reader the suites check written PNGs and JPEGs with (the
// writer lives in sdfrt). One copy, linked by every suite that reads images.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#include <stb_image.h>
