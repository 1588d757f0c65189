#pragma once
// Contract: the one way hairpipe's code reaches Vulkan's functions: volk's declarations under the
// private names of hairpipe's own copy (hpvk_vkCmdDispatch, hpvk_volkInitialize, ...), spelled as volk's
// in the source. Include this, never <volk.h> or a prototype-declaring <vulkan/vulkan.h>, in the
// library, its tools and its tests; installed public headers include only <vulkan/vulkan_core.h>.
#include "hairpipe_volk_names.h"  // generated from volk.h (third_party/volk/generate_names.cmake)

#include <volk.h>
