// stb_image and stb_image_write compiled into the module: the desktop links Debian's
// compiled libstb, which exists for the host only; these are the same headers with their
// implementations switched on.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
