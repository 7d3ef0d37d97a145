// Replay files built to hurt the parser: counts that wrap or exhaust memory, state hashes
// past the end, huge or control-character text. Each is one file:line:col message, escaped
// and bounded, never an allocation failure or an internal error.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "game/records/replay.h"

namespace bz::game {
namespace {

const std::string kHeader =
    "beamzone-replay 1\nversion 0.1.0\nseed 1\nlevel builtin:default\n"
    "level-hash 00000000000000ff\nlives 3\nhash-interval 60\n";

std::string error_of(const std::string& text) {
    try {
        replay::parse(text, "r.bzr");
    } catch (const UserError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("NOT A USER ERROR: ") + e.what();
    }
    return "(no error)";
}

bool printable_only(const std::string& s) {
    for (const char c : s) {
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return false;
    }
    return true;
}

TEST(ReplayHugeCounts, RunLengthNearTwoToTheSixtyFourIsRefusedAtItsColumn) {
    for (const char* count : {"18446744073709551615", "18446744073709551600", "11"}) {
        const std::string msg = error_of(kHeader + "ticks 10\nc " + count + " 0 0 00\nend\n");
        EXPECT_EQ(msg.rfind("r.bzr:9:3: error: run length", 0), 0u) << msg;
    }
    // Two runs whose sum wraps around 2^64.
    const std::string msg =
        error_of(kHeader + "ticks 10\nc 5 0 0 00\nc 18446744073709551612 0 0 00\nend\n");
    EXPECT_EQ(msg.rfind("r.bzr:10:3: error: run length", 0), 0u) << msg;
}

TEST(ReplayHugeCounts, NumbersOutOfRangeAreNamed) {
    const std::string msg = error_of(kHeader + "ticks 99999999999999999999999\nend\n");
    EXPECT_EQ(msg.rfind("r.bzr:8:7: error: tick count", 0), 0u) << msg;
}

TEST(ReplayHugeCounts, StateHashesPastTheDeclaredTicksAreRefusedAtOnce) {
    const std::string msg = error_of(kHeader + "ticks 2\nc 2 0 0 00\nh 3 ab\nend\n");
    EXPECT_EQ(msg.rfind("r.bzr:10:3: error: a state hash at tick 3", 0), 0u) << msg;
    EXPECT_NE(error_of(kHeader + "h 1 ab\n").find("'h' before 'ticks'"), std::string::npos);
}

TEST(ReplayUntrustedText, HugeFieldIsCutInTheMessage) {
    const std::string huge(20u << 20, 'z');
    for (const std::string& text :
         {kHeader + huge + "\n", kHeader + "ticks " + huge + "\n",
          kHeader + "version " + huge + "\n", "beamzone-replay 1\nlevel " + huge + "\n"}) {
        const std::string msg = error_of(text);
        EXPECT_LT(msg.size(), 500u) << msg.substr(0, 200);
        EXPECT_EQ(msg.rfind("r.bzr:", 0), 0u) << msg.substr(0, 200);
    }
}

TEST(ReplayUntrustedText, ControlCharactersAreEscapedOrRefused) {
    for (const std::string& text :
         {kHeader + "\x1b[2J\x1b]0;pwned\x07 1\n", kHeader + "seed 1\x1b[31m\n",
          std::string("beamzone-replay 1\nversion 1") + '\0' + "\x1b[1m\n",
          std::string("beamzone-replay 1\nlevel a\x1b[1mb\n")}) {
        const std::string msg = error_of(text);
        EXPECT_TRUE(printable_only(msg)) << msg;
        EXPECT_EQ(msg.rfind("r.bzr:", 0), 0u) << msg;
    }
}

TEST(ReplayEmptyInput, EmptyAndBlankFilesAreReportedAtLineOne) {
    EXPECT_EQ(error_of(""), "r.bzr:1:1: error: empty file, not a beamzone replay");
    EXPECT_EQ(error_of("\n\n").rfind("r.bzr:2:1: error: empty file", 0), 0u);
}

TEST(ReplayRoundTrip, WrittenFileReadsBack) {
    replay::Replay r;
    r.header.level = "levels/a level.toml";
    r.commands.assign(5, PackedCommand{1, -1, 3});
    r.checks.push_back({5, 0xabc});
    const replay::Replay back = replay::parse(replay::serialise(r), "r.bzr");
    EXPECT_EQ(back.header.level, r.header.level);
    EXPECT_EQ(back.commands.size(), 5u);
    EXPECT_EQ(back.checks.size(), 1u);
}

}  // namespace
}  // namespace bz::game
