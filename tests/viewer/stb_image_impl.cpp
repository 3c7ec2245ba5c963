// stb_image (the reader) for checking written PNGs; the writer lives in sdfrt.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
