// A shared library that is not a voroseal plugin (no voroseal_register_plugin): loading it must
// fail with a clear error, and the other plugins must still load.
extern "C" int voroseal_something_else() { return 42; }
