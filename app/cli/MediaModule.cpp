// MediaModule: the media program is looked for beside /proc/self/exe (the build tree), then where it is
// installed relative to the program (PARTICLELAB_MEDIA_PROGRAM_FROM_BIN: a package of any prefix), then
// in the build's install folder (PARTICLELAB_MEDIA_PROGRAM_DIR).
#include "MediaModule.h"

#include "Commands.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <unistd.h>

namespace pl::cli {

namespace {
constexpr const char* kMediaProgram = "particlelab-cli-media";
}

int execMediaProgram(char** argv) {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    std::string tried;
    const std::filesystem::path bin = error ? std::filesystem::path() : self.parent_path();
    for (const std::filesystem::path& dir :
         {bin, bin.empty() ? bin : (bin / PARTICLELAB_MEDIA_PROGRAM_FROM_BIN).lexically_normal(),
          std::filesystem::path(PARTICLELAB_MEDIA_PROGRAM_DIR)}) {
        if (dir.empty()) continue;
        const std::filesystem::path program = dir / kMediaProgram;
        ::execv(program.c_str(), argv); // returns only on failure
        tried += (tried.empty() ? "" : ", ") + program.string() + " (" + std::strerror(errno) + ")";
    }
    std::cerr << "particlelab-cli: recording and reports need " << kMediaProgram
              << ", which could not be run: " << tried << "\n";
    return kBadInput;
}

} // namespace pl::cli
