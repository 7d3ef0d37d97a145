#include "platform/pref_paths.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace bz::platform {
namespace {

namespace fs = std::filesystem;

// Sets (or, with nullopt, unsets) an environment variable for one scope; the test environment
// sets BEAMZONE_CACHE_DIR for every test, so each case states what it needs.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value)
            ::setenv(name, value->c_str(), 1);
        else
            ::unsetenv(name);
    }
    ~ScopedEnv() {
        if (old_)
            ::setenv(name_, old_->c_str(), 1);
        else
            ::unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

  private:
    const char* name_;
    std::optional<std::string> old_;
};

TEST(PrefPaths, EnvironmentOverrideIsCreatedAndUsed) {
    const fs::path dir =
        fs::temp_directory_path() / ("bz_pref_" + std::to_string(::getpid())) / "nested";
    ::setenv("BEAMZONE_PREF_DIR", dir.c_str(), 1);
    const PrefPaths p = pref_paths();
    ::unsetenv("BEAMZONE_PREF_DIR");
    EXPECT_TRUE(fs::is_directory(dir));
    EXPECT_EQ(p.dir, dir);
    EXPECT_EQ(p.settings, dir / "settings.toml");
    EXPECT_EQ(p.high_scores.parent_path(), dir);
    EXPECT_EQ(p.log.parent_path(), dir);
    EXPECT_EQ(p.gamepad_db, dir / "gamecontrollerdb.txt");
    EXPECT_NE(p.settings, p.high_scores);
    fs::remove_all(dir.parent_path());
}

// The line-method measurement is a cache: BEAMZONE_CACHE_DIR when set; else, under
// BEAMZONE_PREF_DIR alone, that folder (a test's fresh folder stays fresh); else XDG's cache
// folder, ignoring a relative XDG_CACHE_HOME as the spec says, else ~/.cache.
TEST(PrefPaths, TheLineMethodMeasurementGoesToTheCacheFolder) {
    const fs::path root = fs::temp_directory_path() / ("bz_cache_" + std::to_string(::getpid()));
    const ScopedEnv home("HOME", (root / "home").string());
    const ScopedEnv data("XDG_DATA_HOME", (root / "data").string());
    {
        const ScopedEnv pref("BEAMZONE_PREF_DIR", (root / "pref").string());
        const ScopedEnv cache("BEAMZONE_CACHE_DIR", (root / "cache").string());
        EXPECT_EQ(pref_paths().line_methods, root / "cache" / "line-methods.json");
    }
    {
        const ScopedEnv pref("BEAMZONE_PREF_DIR", (root / "pref").string());
        const ScopedEnv cache("BEAMZONE_CACHE_DIR", std::nullopt);
        EXPECT_EQ(pref_paths().line_methods, root / "pref" / "line-methods.json");
    }
    const ScopedEnv pref("BEAMZONE_PREF_DIR", std::nullopt);
    const ScopedEnv cache("BEAMZONE_CACHE_DIR", std::nullopt);
    {
        const ScopedEnv xdg("XDG_CACHE_HOME", (root / "xdg-cache").string());
        const PrefPaths p = pref_paths();
        EXPECT_EQ(p.line_methods, root / "xdg-cache" / "beamzone" / "line-methods.json");
        EXPECT_EQ(p.dir.string().rfind((root / "data").string(), 0), 0u) << p.dir;
    }
    {
        const ScopedEnv xdg("XDG_CACHE_HOME", std::string("relative/cache"));
        EXPECT_EQ(pref_paths().line_methods,
                  root / "home" / ".cache" / "beamzone" / "line-methods.json");
    }
    fs::remove_all(root);
}

}  // namespace
}  // namespace bz::platform
