// A shared library that is no plugin: loadPlugin must say so.
extern "C" int plain_library_answer() { return 42; }
