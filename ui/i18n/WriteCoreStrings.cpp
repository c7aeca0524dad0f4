// particlelab_core_strings: writes the core's visible texts as QT_TRANSLATE_NOOP lines into the file
// named on the command line, for lupdate (ui/CMakeLists.txt runs it before update_translations).
#include "CoreStrings.h"

#include <cstdio>
#include <fstream>
#include <sstream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: particlelab_core_strings OUTPUT.cpp\n");
        return 2;
    }
    const std::string source = pl::ui::coreStringsSource(pl::ui::coreDisplayStrings());
    {
        // Unchanged text keeps the file's time stamp, so lupdate's inputs only change when a text does.
        std::ifstream existing(argv[1], std::ios::binary);
        std::ostringstream old;
        old << existing.rdbuf();
        if (existing && old.str() == source) return 0;
    }
    std::ofstream out(argv[1], std::ios::binary | std::ios::trunc);
    out << source;
    if (!out) {
        std::fprintf(stderr, "particlelab_core_strings: cannot write %s\n", argv[1]);
        return 4;
    }
    return 0;
}
