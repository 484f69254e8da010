// nbscope-plugin-host: the process a detector plugin runs in (io/plugin_host.hpp). nbscope starts it;
// it ends when nbscope closes its socket, or with the guard's one line when the plugin crashes or hangs.
#include <unistd.h>

#include <cstdio>

#include "io/plugin_host.hpp"

int main(int argc, char** argv) {
  const int code = nbscope::serve_plugin_host(argc, argv);
  std::fflush(nullptr);
  ::_exit(code);  // no exit-time leak check of the plugin's memory: nbscope's tests judge nbscope
}
