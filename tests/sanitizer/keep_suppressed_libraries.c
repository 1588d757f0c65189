/* Preloaded into every process of the sanitizer suite (`make test-asan`, LD_PRELOAD): keeps the
 * libraries that tests/sanitizer/lsan.supp names loaded until the process ends.
 *
 * Why: the Vulkan loader unloads the driver (lavapipe) and the validation layer when the last instance is
 * destroyed. LeakSanitizer reports at exit, when those libraries are gone, so the caches they never free
 * show as two-frame stacks ending in "<unknown module>", which no suppression can name. Opening each
 * library once more with RTLD_NODELETE keeps it mapped (the loader's dlopen gets the same handle), so its
 * frames keep their library's name and only the libraries the suppression file names are suppressed.
 *
 * The library list is the suppression file itself (one source of truth): every "leak:<name>.so..." line.
 * Does nothing in a process without LeakSanitizer (compilers, cmake, shells the suite starts), and a library
 * that is not installed is simply not kept. Built without sanitizer flags (it runs before any runtime). */
#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

#ifndef HAIRPIPE_LSAN_SUPPRESSIONS
#error "HAIRPIPE_LSAN_SUPPRESSIONS (the suppression file's path) must be defined"
#endif

/* The library name of one suppression line ("leak:libfoo.so.1" -> "libfoo.so.1"), or NULL. */
static const char* suppressed_library(char* line) {
  line[strcspn(line, "\r\n")] = '\0';
  if (strncmp(line, "leak:", 5) != 0 || strstr(line + 5, ".so") == NULL) {
    return NULL;
  }
  return line + 5;
}

__attribute__((constructor)) static void keep_suppressed_libraries(void) {
  if (dlsym(RTLD_DEFAULT, "__lsan_do_leak_check") == NULL) {
    return; /* not a sanitized process */
  }
  FILE* file = fopen(HAIRPIPE_LSAN_SUPPRESSIONS, "r");
  if (file == NULL) {
    return;
  }
  char line[512];
  while (fgets(line, sizeof line, file) != NULL) {
    const char* library = suppressed_library(line);
    if (library != NULL) {
      (void)dlopen(library, RTLD_NOW | RTLD_NODELETE);
    }
  }
  fclose(file);
}
