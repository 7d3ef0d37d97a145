#include "game/records/highscores.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>

#include "core/error.h"
#include "core/io/file_io.h"
#include "support/scratch_dir.h"

namespace bz::game {
namespace {

namespace fs = std::filesystem;

using TempDir = bz::test::ScratchDir;

TEST(HighScores, DefaultsAreSortedAndFull) {
    const HighScoreTable t = HighScoreTable::defaults();
    ASSERT_EQ(t.entries().size(), HighScoreTable::kSize);
    for (std::size_t i = 1; i < t.entries().size(); ++i) {
        EXPECT_GE(t.entries()[i - 1].score, t.entries()[i].score);
    }
    EXPECT_EQ(t.best(), t.entries()[0].score);
}

TEST(HighScores, InsertRanksAndDropsTheLowest) {
    HighScoreTable t = HighScoreTable::defaults();
    const int lowest = t.entries().back().score;
    EXPECT_FALSE(t.qualifies(lowest));
    EXPECT_FALSE(t.insert({"LOW", lowest}).has_value());
    const auto rank = t.insert({"new", 1'000'000});
    ASSERT_TRUE(rank.has_value());
    EXPECT_EQ(*rank, 0u);
    EXPECT_EQ(t.entries()[0].initials, "NEW");
    EXPECT_EQ(t.entries().size(), HighScoreTable::kSize);
    // Equal scores go after the older entry.
    const int second = t.entries()[1].score;
    EXPECT_EQ(*t.insert({"TIE", second}), 2u);
}

HighScoreBook book_of(const HighScoreTable& t) {
    HighScoreBook b;
    b.set(level_key("Classic", 0x1234), t);
    return b;
}

TEST(HighScores, SerialiseParseRoundTrip) {
    HighScoreTable t = HighScoreTable::defaults();
    t.insert({"A B", 123456});
    HighScoreBook book = book_of(t);
    book.set(level_key("Easy one", 0xfedcba9876543210), HighScoreTable::defaults());
    book.set(kSharedTableKey, t);
    const HighScoreParse back = parse_highscores(serialise(book), "hs");
    EXPECT_TRUE(back.errors.empty()) << back.errors.front();
    EXPECT_EQ(back.book, book);
}

TEST(HighScores, CorruptOrPartialFilesAreReportedWithLineAndColumn) {
    HighScoreTable t = HighScoreTable::defaults();
    t.insert({"ZZZ", 500000});
    const std::string good = serialise(book_of(t));

    struct Case {
        std::string text;
        std::string expect;
    };
    const Case cases[] = {
        {good.substr(0, good.size() / 2), "hs:"},         // cut mid-line
        {good.substr(0, good.find("EDR")), "cut short"},  // cut at a line end
        {"garbage\n", "hs:1:1: error: not a beamzone high-score file"},
        {"beamzone-highscores 1\nABC 12x\nend\n", "hs:2:5: error: score '12x'"},
        {"beamzone-highscores 1\nab 5\nend\n", "hs:2:1: error: expected three initials"},
        {std::string("beamzone-highscores 1\nA") + '\0' + "C 5\nend\n", "hs:2:2: error: initials"},
        {"beamzone-highscores 2\nABC 5\nend\n", "hs:2:1: error: an entry before the first"},
        {"", "hs:1:1: error: empty"},
    };
    for (const Case& c : cases) {
        const HighScoreParse r = parse_highscores(c.text, "hs");
        ASSERT_FALSE(r.errors.empty()) << c.text;
        EXPECT_NE(r.errors.front().find(c.expect), std::string::npos) << r.errors.front();
    }
}

TEST(HighScores, FailedWriteLeavesTheOldFileIntact_InjectedWriter) {
    TempDir dir("bz_hs_inject");
    const fs::path f = dir.path() / "highscores.txt";
    save_highscores(f, book_of(HighScoreTable::defaults()));
    const std::string before = read_file(f);
    HighScoreTable t = HighScoreTable::defaults();
    t.insert({"NEW", 999999});
    // A writer that dies half way through, as a crash or full disk would.
    const FileWriter failing = [](const fs::path& p, std::string_view bytes) {
        write_file_atomic(p.string() + ".partial", bytes.substr(0, bytes.size() / 2));
        throw UserError(p.string() + ": write failed: injected");
    };
    EXPECT_THROW(save_highscores(f, book_of(t), failing), UserError);
    EXPECT_EQ(read_file(f), before);
    EXPECT_EQ(load_highscores(f).book, book_of(HighScoreTable::defaults()));
}

TEST(HighScores, FailedWriteLeavesTheOldFileIntact_RealWriteFailsMidway) {
    TempDir dir("bz_hs_fsize");
    const fs::path f = dir.path() / "highscores.txt";
    save_highscores(f, book_of(HighScoreTable::defaults()));
    const std::string before = read_file(f);
    HighScoreTable t = HighScoreTable::defaults();
    for (int i = 0; i < 10; ++i) t.insert({"BIG", 10'000'000 + i});
    ASSERT_GT(serialise(book_of(t)).size(), 64u);

    // Limit file size so the real write(2) of the temp file fails after 64 bytes (EFBIG), as a
    // full disk would; SIGXFSZ is ignored so the process sees the error instead of dying.
    rlimit old{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
    auto* old_handler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = old;
    small.rlim_cur = 64;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
    bool threw = false;
    std::string message;
    try {
        save_highscores(f, book_of(t));
    } catch (const UserError& e) {
        threw = true;
        message = e.what();
    }
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, old_handler);

    EXPECT_TRUE(threw);
    EXPECT_NE(message.find("write failed"), std::string::npos) << message;
    EXPECT_EQ(read_file(f), before) << "the old table survives";
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++files;
    EXPECT_EQ(files, 1) << "no temp file is left behind";
}

TEST(HighScores, CleanInitials) {
    EXPECT_EQ(clean_initials("ab"), "AB ");
    EXPECT_EQ(clean_initials("a-b-c-d"), "ABC");
    EXPECT_EQ(clean_initials(""), "   ");
}

}  // namespace
}  // namespace bz::game
