#include "geometry/import/import_failure.h"

#include "core/error.h"
#include "core/text/printable.h"

namespace bz::geo {

void fail_import(const std::filesystem::path& path, const std::string& reason) {
    std::string line = printable(path.string()) + ": error: " + printable_message(reason);
    for (char& c : line) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    throw UserError(line);
}

}  // namespace bz::geo
