// Linked into the executables of the sanitizer build only (HEMIRAD_SANITIZE, ci/sanitize).
// Mesa's eglTerminate dlcloses its GL driver (swrast_dri.so); LeakSanitizer reports at exit, when
// the driver is gone, so a leak inside it names no library and no ci/lsan.supp entry can match
// it. This dlclose, which the executable's definition makes the process-wide one, keeps every
// library mapped (as exit would have anyway) so that reports name where they come from.
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
