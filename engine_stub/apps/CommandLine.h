#pragma once
// The start the engine's command-line programs share (cube_game, fxbench): the command line
// parsed, --help answered, a bad command line refused with the usage.
#include <cstdio>
#include <string>

namespace cube {

/// Parses argv into *options with `parse`. A refused command line prints "`tool`: <error>" and
/// the usage on stderr and gives 2; --help (options->help) prints the usage on stdout and gives
/// 0; otherwise -1: the program goes on.
template <class Options>
int parseCommandLine(const char* tool, int argc, const char* const* argv,
                     bool (*parse)(int, const char* const*, Options*, std::string*), std::string (*usage)(),
                     Options* options) {
    std::string error;
    if (!parse(argc, argv, options, &error)) {
        std::fprintf(stderr, "%s: %s\n%s", tool, error.c_str(), usage().c_str());
        return 2;
    }
    if (options->help) {
        std::printf("%s", usage().c_str());
        return 0;
    }
    return -1;
}

}  // namespace cube
