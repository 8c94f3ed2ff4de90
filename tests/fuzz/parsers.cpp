// The fuzz build compiles tinyobjloader and tinygltf here, from the headers Debian ships (the
// same source its shared libraries are built from), so that libFuzzer sees their branches and
// ASan their memory. The normal build links Debian's shared libraries instead.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
