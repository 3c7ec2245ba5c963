// The one translation unit that compiles stb_image_write.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO  // we only encode to memory; AtomicFile does the I/O
#include <stb_image_write.h>
