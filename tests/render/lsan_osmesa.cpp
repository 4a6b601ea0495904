// OSMesa keeps one small buffer record per OSMesaMakeCurrent size in a process-wide list and
// never frees it (there is no API to), so LeakSanitizer reports it at exit in the asan preset.
// This hook, linked into the tests that create GL contexts, suppresses leaks inside libOSMesa
// only; leaks in our code are still reported. It does nothing without LeakSanitizer.
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }
