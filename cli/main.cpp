#include <iostream>

#include "cli.hpp"
#include "interrupt.hpp"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  ogive::cli::install_interrupt_handlers();
  return ogive::cli::run_cli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
