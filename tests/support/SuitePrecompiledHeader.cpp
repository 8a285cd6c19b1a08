// The target lacrima_suite_pch exists for its precompiled header, which every QtTest suite
// reuses (tests/CMakeLists.txt); this object is never linked.
