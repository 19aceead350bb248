// tool_main.cpp: main() of every shadertwin tool, the built-in one and each
// a user builds with shadertwin_add_technique (the package installs this
// file for that).
#include "sdk/tool.h"

int main(int argc, char** argv) { return st::run_tool(argc, argv); }
