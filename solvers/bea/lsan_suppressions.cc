// LeakSanitizer: CLN (GiNaC's number library) allocates 26 bytes during its
// static initialisation and never frees them; every program that links
// GiNaC would otherwise fail under ASan with detect_leaks=1. Compiled into
// each executable that links vivp_bea (an INTERFACE source), only in
// sanitizer builds. The suppression report is silenced so that command-line
// tests comparing stderr line by line see only the program's own output.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libcln.so\n";
}

extern "C" const char* __lsan_default_options() {
  return "print_suppressions=0";
}
