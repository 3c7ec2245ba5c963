// stb_image (the PNG reader) for checking the CLI's output; the writer is in sdfrt.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
