// penumbra-sandbox with the tests' tiny technique registered next to the built-ins: the Xvfb
// test drives the real window, UI and script code through it.
#include "sandbox/sandbox_main.h"
#include "tiny_technique.h"

int main(int argc, char** argv) {
  return penumbra::sandbox::sandbox_main(argc, argv, penumbra::sandbox_test::register_tiny_technique);
}
