#include "app/cli.hpp"

int main(int argc, char** argv) {
  hv::app::applyProgramDefaults();
  return hv::app::runCli(std::vector<std::string>(argv + 1, argv + argc));
}
