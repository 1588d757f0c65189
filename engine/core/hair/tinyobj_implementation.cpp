// tinyobjloader (libtinyobjloader-dev, a single header) compiled into hairpipe's core, so the installed
// library carries it and an application links nothing for it. Built without the sanitizers (as Debian's
// shared library is): its parser converts out-of-range floats to int in lines hairpipe never uses (`vw`
// skin weights), which UBSan reports while fuzzing the OBJ reader; hairpipe's own code around it is checked.
#define TINYOBJLOADER_IMPLEMENTATION
#include "engine/core/hair/tinyobj_config.h"
