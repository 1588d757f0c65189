// tinygltf (libtinygltf-dev, a single header) compiled into hairpipe's core, as tinyobjloader is, so the
// installed library carries it and an application links nothing for it. It parses JSON and buffers only
// (tinygltf_config.h).
#define TINYGLTF_IMPLEMENTATION
#include "engine/core/hair/tinygltf_config.h"
