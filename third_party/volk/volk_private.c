/* hairpipe's private copy of volk (libvulkan-volk-dev ships it as source): every global it defines is
   renamed hpvk_* by the generated names header, so the library defines no vk* or volk* symbol. */
#include "hairpipe_volk_names.h"
#include <volk.c>
