// The frob command line: thin, it parses arguments and calls the libraries.
#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"Frob Sandbox: functional reactive robot controllers, simulated headlessly", "frob"};
  app.set_version_flag("--version", FROB_VERSION);
  app.require_subcommand(0, 1);
  CLI11_PARSE(app, argc, argv);
  if (app.get_subcommands().empty()) {
    std::cout << app.help();
  }
  return 0;
}
