// A shared library that is not a Penumbra plugin: it has no PENUMBRA_PLUGIN entry points, so
// the host must refuse it by name.
extern "C" __attribute__((visibility("default"))) int not_a_penumbra_plugin() { return 42; }
