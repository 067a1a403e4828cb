// LeakSanitizer: CLN (GiNaC's number library) allocates 26 bytes during its
// static initialisation and never frees them; every program that links
// GiNaC would otherwise fail under ASan with detect_leaks=1. Compiled into
// each executable that links vivp_bea (an INTERFACE source), only in
// sanitizer builds.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libcln.so\n";
}
