// Built into the sanitizer build only (DATOMSIM_SANITIZE): what LeakSanitizer must not report.
//
// Drawing text fills fontconfig's process-wide caches, which live until exit by design; every
// picture would otherwise end the run as a "leak". Only allocations made inside fontconfig are
// suppressed, so a leak of datomsim's own still fails the run.
// Visible: the sanitizer runtime looks it up in the executable (the build hides symbols).
extern "C" __attribute__((visibility("default"))) const char* __lsan_default_suppressions() {
  return "leak:libfontconfig.so\n";
}

// Quiet about the suppressions it used: --quiet promises an empty standard error, and the list
// would be printed at every exit that drew text.
extern "C" __attribute__((visibility("default"))) const char* __lsan_default_options() {
  return "print_suppressions=0";
}
