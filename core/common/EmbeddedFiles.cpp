// Lookup of embedded resource files.
#include "EmbeddedFiles.h"

namespace pl {

const EmbeddedFile* findEmbeddedFile(std::string_view path) {
    for (const auto& f : embeddedFiles())
        if (f.path == path) return &f;
    return nullptr;
}

} // namespace pl
