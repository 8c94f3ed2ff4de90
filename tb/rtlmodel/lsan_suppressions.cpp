// Verilator 5.006's Verilated::catName keeps a thread_local buffer it never frees, so every thread
// that builds an RTL model (the lab's workers, tile-parallel models) leaks it when it ends: not
// ours to fix. Linked into every program that links the RTL in the sanitizer tree
// (tb/rtlmodel/CMakeLists.txt).
extern "C" const char* __lsan_default_suppressions() { return "leak:Verilated::catName\n"; }
