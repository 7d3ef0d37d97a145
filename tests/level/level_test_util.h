#pragma once
// Helpers for feeding level text to the loader in tests: a scratch folder per test that acts
// as both the level's folder and the data/ root, so model-path rules can be exercised.
// Header-only: tests/CMakeLists.txt compiles only *_test.cpp files.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "level/loader.h"
#include "support/scratch_dir.h"

namespace bz::level::test {

// A scratch folder per test that acts as both the level's folder and the data/ root.
using ScratchDir = bz::test::ScratchDir;

// The smallest valid level (two lines) with `body` appended.
// Loads level text as "levels/test.toml" with a data/ root that does not exist, so no model
// path can resolve into the real data folder.
inline LoadResult load_text(std::string_view text, LoadOptions options = {}) {
    options.data_root = "/nonexistent-data";
    return load_level_string(text, "levels/test.toml", options);
}

inline std::string level_text(std::string_view body) {
    return "version = 1\nname = \"Test level\"\n" + std::string(body);
}

// Checks that `result` holds exactly one error, at line:column, whose message contains
// `fragment`, and no level.
inline ::testing::AssertionResult has_one_error(const LoadResult& result, int line, int column,
                                                std::string_view fragment) {
    std::string all;
    for (const auto& e : result.errors) all += "\n  " + format(e);
    if (result.errors.size() != 1) {
        return ::testing::AssertionFailure()
               << "expected 1 error, got " << result.errors.size() << all;
    }
    const Diagnostic& d = result.errors.front();
    if (d.pos.line != line || d.pos.column != column) {
        return ::testing::AssertionFailure()
               << "expected the error at " << line << ":" << column << all;
    }
    if (d.message.find(fragment) == std::string::npos) {
        return ::testing::AssertionFailure()
               << "expected the message to contain '" << fragment << "'" << all;
    }
    if (result.level) return ::testing::AssertionFailure() << "a level came back despite the error";
    return ::testing::AssertionSuccess();
}

}  // namespace bz::level::test
