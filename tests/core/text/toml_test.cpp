// core/text/toml.h: the corrected whitespace lookup agrees with toml++'s shipped one wherever
// that one is defined, answers "not whitespace" where it was not, and every TOML reader goes
// through the header.
#include "core/text/toml.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "support/tree_paths.h"

namespace {

// Where the shipped lookup reaches its TOML_UNREACHABLE default: the 64 blocks of 0x3FA code
// points from U+00A0 whose mask bit is clear and which no case of its switch handles.
bool shipped_lookup_is_undefined(char32_t c) {
    if (c < U'\xA0' || c > U'\uFEFF') return false;
    if (c == U'\xA0' || c == U'\u3000' || c == U'\uFEFF') return false;
    const std::uint64_t block = (static_cast<std::uint64_t>(c) - 0xA0u) / 0x3FAu;
    if ((std::uint64_t{1} << block) & 0x7FFFFFFFFFFFF75Eull) return false;
    return block != 5 && block != 7;
}

TEST(TomlHeader, WhitespaceLookupMatchesTheShippedOneWhereThatIsDefined) {
    int compared = 0;
    int undefined = 0;
    for (char32_t c = 0x80; c <= 0x10FFFF; ++c) {
        if (c >= 0xD800 && c <= 0xDFFF) continue;
        if (shipped_lookup_is_undefined(c)) {
            ++undefined;
            EXPECT_FALSE(toml::impl::is_non_ascii_horizontal_whitespace(c)) << std::hex << +c;
            continue;
        }
        ++compared;
        ASSERT_EQ(toml::impl::is_non_ascii_horizontal_whitespace(c),
                  toml::impl::is_non_ascii_horizontal_whitespace_as_shipped(c))
            << std::hex << +c;
    }
    EXPECT_GT(compared, 1000000);
    EXPECT_GT(undefined, 0);  // the header's reason to exist
    EXPECT_TRUE(shipped_lookup_is_undefined(U'\u031C'));
    EXPECT_TRUE(shipped_lookup_is_undefined(U'\u00E9'));
}

TEST(TomlHeader, NonAsciiOutsideStringsIsAPositionedError) {
    // U+031C (from the settings fuzz target's input), U+00E9, U+00A7 after a line-ending
    // backslash in a multi-line string (upstream issue 190), U+30A2 and U+FB10: each once took
    // the undefined path.
    struct Case {
        std::string text;
        bool parses;
        int line, column;
    };
    const std::vector<Case> cases = {
        {"a = 1\xCC\x9C\n", false, 1, 6},
        {"name = caf\xC3\xA9\n", false, 1, 8},
        {"\xC3\xA9 = 1\n", false, 1, 1},
        {"s = \"\"\"\\\n\xC2\xA7\"\"\"\n", true, 0, 0},
        {"a = [1,\xE3\x82\xA2 2]\n", false, 1, 8},
        {"t = {x = 1\xEF\xAC\x90}\n", false, 1, 11},
        {"a = 1\xC2\xA0\n", false, 1, 6},  // U+00A0: whitespace to toml++, an error in TOML
        // A broken parser invariant (parse_key on a '['): an error, not an abort or an assumption.
        {"[[[[", false, 1, 3},
        {"[[a]]\n[[[b]]]\n", false, 2, 3},
    };
    for (const Case& c : cases) {
        try {
            const toml::table t =
                toml::parse(std::string_view(c.text), std::string_view("case.toml"));
            EXPECT_TRUE(c.parses) << c.text;
        } catch (const toml::parse_error& e) {
            EXPECT_FALSE(c.parses) << c.text << ": " << e.description();
            EXPECT_EQ(e.source().begin.line, static_cast<unsigned>(c.line)) << c.text;
            EXPECT_EQ(e.source().begin.column, static_cast<unsigned>(c.column)) << c.text;
        }
    }
}

TEST(TomlHeader, EverySourceIncludesTomlThroughTheHeader) {
    namespace fs = std::filesystem;
    // Built in two pieces so this file does not match itself.
    const std::string direct = std::string("#include <toml") + "++/";
    int readers = 0;
    for (const char* tree : {"src", "tests"}) {
        for (const auto& entry : fs::recursive_directory_iterator(bz::test::source_dir() / tree)) {
            const std::string ext = entry.path().extension().string();
            if (ext != ".cpp" && ext != ".h") continue;
            std::ifstream in(entry.path());
            std::stringstream text;
            text << in.rdbuf();
            const std::string s = text.str();
            const bool is_header = entry.path().filename() == "toml.h" &&
                                   entry.path().parent_path().filename() == "text";
            if (!is_header) {
                EXPECT_EQ(s.find(direct), std::string::npos)
                    << entry.path() << " includes toml++ directly: use core/text/toml.h";
            }
            if (s.find("\"core/text/toml.h\"") != std::string::npos) ++readers;
        }
    }
    EXPECT_GE(readers, 4);  // levels, settings, the implementation and this test at least
}

}  // namespace
