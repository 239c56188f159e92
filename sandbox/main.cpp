// penumbra-sandbox: see sandbox_main.cpp and docs/sandbox.md.
#include "sandbox/sandbox_main.h"

int main(int argc, char** argv) { return penumbra::sandbox::sandbox_main(argc, argv); }
