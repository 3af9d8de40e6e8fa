// deepguide: guidance planning and analysis for autonomous underwater vehicles
// (the commands: apps/cli.cpp).

#include "commands.hpp"

int main(int argc, char** argv) { return deepguide::app::run(argc, argv); }
