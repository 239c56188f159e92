// penumbra-sandbox: see sandbox_main.cpp and docs/sandbox.md.
#include <cstdio>
#include <exception>
#include <new>

#include "sandbox/sandbox_main.h"

// Like the CLI's: an exception nothing handled is exit 1 with its words, never std::terminate's
// SIGABRT (inputs are capped where they enter, so this is a bug, not bad input).
int main(int argc, char** argv) {
  try {
    return penumbra::sandbox::sandbox_main(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "penumbra-sandbox: internal error: out of memory\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "penumbra-sandbox: internal error: %s\n", e.what());
  }
  return 1;
}
