// A damaged high-score file (one bad line, cut short, unreadable, not ours) and files of the
// old one-table format: valid entries are never lost, the damaged file is kept aside as
// NAME.bad-DATE rather than overwritten, and there is one message to show.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/io/file_io.h"
#include "game/records/highscores.h"
#include "support/scratch_dir.h"

namespace bz::game {
namespace {

namespace fs = std::filesystem;

// A scratch folder for a high-score file, which lists the damaged files kept aside in it.
struct ScoresDir : bz::test::ScratchDir {
    using ScratchDir::ScratchDir;
    fs::path file() const { return path() / "highscores.toml"; }
    // Writes `text` as the high-score file and loads it.
    HighScoreLoad load_text(const std::string& text) const {
        write_file_atomic(file(), text);
        return load_highscores(file());
    }
    std::vector<fs::path> set_aside() const {
        std::vector<fs::path> out;
        for (const auto& e : fs::directory_iterator(path())) {
            if (e.path().filename().string().find(".bad-") != std::string::npos)
                out.push_back(e.path());
        }
        return out;
    }
};

const LevelKey kClassic = level_key("Classic", 0xabc);

TEST(HighScoresDamagedFile, OneBadLineKeepsEveryValidEntryAndTheFileAside) {
    ScoresDir dir("bz_hs_bad_line");
    const fs::path f = dir.file();
    const std::string text =
        "beamzone-highscores 2\nlevel 0000000000000abc Classic\nAAA 900\nB!B 800\nCCC 700\n"
        "end\n";
    const HighScoreLoad load = dir.load_text(text);
    ASSERT_EQ(load.errors.size(), 1u);
    EXPECT_NE(load.errors[0].find("highscores.toml:4:2: error: initials"), std::string::npos)
        << load.errors[0];
    const HighScoreTable t = load.book.table(kClassic);
    ASSERT_EQ(t.entries().size(), 2u);
    EXPECT_EQ(t.entries()[0], (HighScore{"AAA", 900}));
    EXPECT_EQ(t.entries()[1], (HighScore{"CCC", 700}));
    // The damaged file is kept byte for byte; the valid entries are written back at once.
    const auto aside = dir.set_aside();
    ASSERT_EQ(aside.size(), 1u);
    EXPECT_EQ(aside[0], load.kept_aside);
    EXPECT_EQ(read_file(aside[0]), text);
    EXPECT_EQ(load_highscores(f).book.table(kClassic), t);
    EXPECT_TRUE(load_highscores(f).errors.empty());
    EXPECT_TRUE(load.may_save);
    EXPECT_NE(load.message.find("kept as highscores.toml.bad-"), std::string::npos) << load.message;
    EXPECT_NE(load.message.find("2 valid entries"), std::string::npos) << load.message;
}

TEST(HighScoresDamagedFile, CutShortFileKeepsWhatWasWritten) {
    ScoresDir dir("bz_hs_cut");
    const HighScoreLoad load =
        dir.load_text("beamzone-highscores 2\nlevel 0000000000000abc Classic\nAAA 900\nBB");
    EXPECT_FALSE(load.errors.empty());
    EXPECT_EQ(load.book.table(kClassic).entries().size(), 1u);
    EXPECT_EQ(dir.set_aside().size(), 1u);
}

TEST(HighScoresDamagedFile, ForeignOrUnreadableFileIsKeptAsideNotOverwritten) {
    ScoresDir dir("bz_hs_foreign");
    const fs::path f = dir.file();
    const HighScoreLoad load = dir.load_text("[my]\nnotes = 1\n");
    EXPECT_EQ(load.book.entry_count(), 0u);
    ASSERT_EQ(dir.set_aside().size(), 1u);
    EXPECT_EQ(read_file(dir.set_aside()[0]), "[my]\nnotes = 1\n");
    EXPECT_FALSE(fs::exists(f)) << "nothing valid to write back";

    // A folder where the file should be: moved aside too, never deleted.
    ScoresDir dir2("bz_hs_folder");
    fs::create_directory(dir2.file());
    const HighScoreLoad folder = load_highscores(dir2.file());
    EXPECT_FALSE(folder.errors.empty());
    EXPECT_EQ(dir2.set_aside().size(), 1u);
}

TEST(HighScoresDamagedFile, FileThatCannotBeMovedAsideIsNeverSaved) {
    ScoresDir dir("bz_hs_ro");
    // A 235-byte name: NAME.bad-DATE (24 more) is over the 255-byte limit, so the rename fails
    // for root too (a read-only folder would not stop root).
    const fs::path f = dir.path() / (std::string(230, 'h') + ".toml");
    write_file_atomic(f, "junk\n");
    const HighScoreLoad load = load_highscores(f);
    EXPECT_FALSE(load.may_save);
    EXPECT_NE(load.message.find("could not be moved aside"), std::string::npos) << load.message;
    EXPECT_EQ(read_file(f), "junk\n");
}

TEST(HighScoresOldFormat, OneTableFilesAreReadAndKeptUnderTheSharedKey) {
    ScoresDir dir("bz_hs_v1");
    const fs::path f = dir.file();
    const HighScoreLoad load = dir.load_text("beamzone-highscores 1\nAAA 900\nBBB 800\nend\n");
    EXPECT_TRUE(load.errors.empty());
    EXPECT_TRUE(dir.set_aside().empty());
    ASSERT_TRUE(load.book.has(kSharedTableKey));
    EXPECT_EQ(load.book.table(kSharedTableKey).entries().size(), 2u);
    // Saved again (format 2), the old entries are still there beside a level's new table.
    HighScoreBook book = load.book;
    HighScoreTable classic = book.table(kClassic);
    classic.insert({"NEW", 999999});
    book.set(kClassic, classic);
    save_highscores(f, book);
    const HighScoreLoad again = load_highscores(f);
    EXPECT_TRUE(again.errors.empty()) << again.errors.front();
    EXPECT_EQ(again.book.table(kSharedTableKey).entries()[1], (HighScore{"BBB", 800}));
    EXPECT_EQ(again.book.table(kClassic).best(), 999999);
}

TEST(HighScoresPerLevel, LevelsAndRulesKeepSeparateTables) {
    HighScoreBook book;
    HighScoreTable easy = HighScoreTable::defaults();
    easy.insert({"EZY", 5'000'000});
    book.set(level_key("Easy", 1), easy);
    EXPECT_EQ(book.table(level_key("Easy", 1)).best(), 5'000'000);
    EXPECT_EQ(book.table(level_key("Classic", 1)), HighScoreTable::defaults());
    EXPECT_EQ(book.table(level_key("Easy", 2)), HighScoreTable::defaults()) << "rules differ";
    const HighScoreParse back = parse_highscores(serialise(book), "hs");
    EXPECT_EQ(back.book, book);
}

TEST(HighScoresPerLevel, HostileLevelNamesAreStoredOnOneSafeLine) {
    const LevelKey k = level_key(std::string("a\nb\x1b[2J") + std::string(500, 'x'), 7);
    EXPECT_EQ(k.name.size(), kMaxLevelNameBytes);
    EXPECT_EQ(k.name.find('\n'), std::string::npos);
    EXPECT_EQ(k.name.find('\x1b'), std::string::npos);
    HighScoreBook book;
    book.set(k, HighScoreTable::defaults());
    const HighScoreParse back = parse_highscores(serialise(book), "hs");
    EXPECT_TRUE(back.errors.empty()) << back.errors.front();
    EXPECT_EQ(back.book, book);
}

TEST(HighScoresPerLevel, ThousandsOfBadLinesGiveAtMostOneHundredMessages) {
    std::string text = "beamzone-highscores 2\n";
    for (int i = 0; i < 5000; ++i) text += "?\n";
    const HighScoreParse r = parse_highscores(text, "hs");
    ASSERT_EQ(r.errors.size(), 100u);
    EXPECT_NE(r.errors.back().find("more errors not shown"), std::string::npos);
}

}  // namespace
}  // namespace bz::game
