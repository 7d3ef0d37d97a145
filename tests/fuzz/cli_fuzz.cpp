// libFuzzer target for the command line: random argument vectors for every command, parsed
// by the commands' own parsers (src/cli: the same code `beamzone` runs, built here without a
// window or GL), then every path they name pushed through the one output writer and the one
// input reader in a scratch folder full of hostile entries (a FIFO, a folder, a foreign file,
// links to an input, a read-only folder). Never a crash, a sanitizer report or a hang (a FIFO
// opened for reading blocks; libFuzzer's -timeout catches it); every message is printable (no
// raw control byte: untrusted text is escaped where it is inserted) and bounded; the inputs,
// the FIFO and the folder are never replaced.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands/camera_args.h"
#include "cli/bench_args.h"
#include "cli/check_args.h"
#include "cli/cli_args.h"
#include "cli/compare_args.h"
#include "cli/difficulty_args.h"
#include "cli/play_args.h"
#include "cli/reference_args.h"
#include "cli/render_args.h"
#include "cli/replay_args.h"
#include "core/error.h"
#include "core/io/file_io.h"
#include "core/io/output_path.h"
#include "core/text/printable.h"
#include "scene/camera_check.h"

namespace fs = std::filesystem;

namespace {

fs::path g_scratch;                // the fuzzer's own folder, made once
std::set<std::string> g_baseline;  // what it holds between runs
std::string g_level_text;          // the input's bytes, which must never change

// A message must be printable (untrusted parts were escaped) and bounded.
void check_message(std::string_view m) {
    if (m.size() > 4000) __builtin_trap();
    for (const char ch : m) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x20 || c == 0x7f) __builtin_trap();
    }
    // No bidi override survives: U+202E is e2 80 ae.
    if (m.find("\xe2\x80\xae") != std::string_view::npos) __builtin_trap();
}

// Any path becomes a name inside the scratch folder (never elsewhere: this runs as root).
fs::path confine(std::string_view word) {
    std::string name;
    for (const char c : word.substr(0, 80)) name += (c == '/' || c == '\0') ? '_' : c;
    if (name.empty() || name == "." || name == "..") name = "x";
    return g_scratch / name;
}

void make_scratch() {
    // On tmpfs where there is one: every write is fsynced, which a disk makes slow.
    std::string tmpl =
        fs::is_directory("/dev/shm") ? "/dev/shm/bz-cli-fuzz-XXXXXX" : "/tmp/bz-cli-fuzz-XXXXXX";
    if (!::mkdtemp(tmpl.data())) std::abort();
    g_scratch = tmpl;
    std::atexit([] {
        std::error_code ec;
        fs::remove_all(g_scratch, ec);
    });
    g_level_text = "version = 1\nname = \"Mine\"\n";
    bz::write_file_atomic(g_scratch / "in.toml", g_level_text);
    bz::write_file_atomic(g_scratch / "foreign.png", "not a picture\n");
    bz::write_file_atomic(g_scratch / "old.png", std::string("\x89PNG\r\n\x1a\n", 8) + "rest");
    bz::write_file_atomic(g_scratch / "old.json", "{}\n");
    ::mkfifo((g_scratch / "fifo.png").c_str(), 0644);
    ::mkfifo((g_scratch / "fifo.toml").c_str(), 0644);
    fs::create_directory(g_scratch / "dir.png");
    fs::create_directory(g_scratch / "out");
    fs::create_symlink(g_scratch / "in.toml", g_scratch / "link.png");
    fs::create_symlink(g_scratch / "in.toml", g_scratch / "out" / "summary.json");
    fs::create_symlink(g_scratch / "fifo.png", g_scratch / "out" / "frametime.png");
    for (const auto& e : fs::recursive_directory_iterator(g_scratch))
        g_baseline.insert(e.path().string());
}

// Removes what a run wrote, so every run starts from the same folder.
void restore_scratch() {
    std::vector<fs::path> extra;
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(g_scratch, ec)) {
        if (!g_baseline.contains(e.path().string())) extra.push_back(e.path());
    }
    for (const fs::path& p : extra) fs::remove_all(p, ec);
    if (fs::symlink_status(g_scratch / "fifo.png").type() != fs::file_type::fifo) __builtin_trap();
    if (!fs::is_directory(fs::symlink_status(g_scratch / "dir.png"))) __builtin_trap();
    if (bz::read_file(g_scratch / "in.toml") != g_level_text) __builtin_trap();
    // --overwrite may have replaced it.
    if (bz::read_file(g_scratch / "foreign.png") != "not a picture\n")
        bz::write_file_atomic(g_scratch / "foreign.png", "not a picture\n");
}

enum class Out { png, json, replay };

void use_output(std::string_view option, const std::string& word, Out kind, bool overwrite) {
    if (word.empty()) return;
    const fs::path out = confine(word);
    const fs::path inputs[] = {g_scratch / "in.toml"};
    const bz::OutputKind& k = kind == Out::png    ? bz::kPngOutput
                              : kind == Out::json ? bz::kJsonOutput
                                                  : bz::kReplayOutput;
    bz::check_output_file(option, out, k, inputs, overwrite);
    bz::write_file_atomic(out, std::string(k.magic) + "written by the fuzzer\n");
}

void use_output_dir(std::string_view option, const std::string& word, bool overwrite) {
    const fs::path inputs[] = {g_scratch / "in.toml"};
    constexpr std::string_view subs[] = {"masks"};
    bz::check_output_dir(option, confine(word), inputs, subs, overwrite);
}

void use_input(std::string_view word) {
    if (!word.empty()) (void)bz::read_file(confine(word), 1u << 16);
}

// The parsed camera must give a picture or be refused: camera_for never passes a camera the
// check would refuse.
void use_camera(const bz::app::CameraArgs& camera) {
    bz::geo::Bounds b;
    b.min = glm::vec3(-1.0f);
    b.max = glm::vec3(1.0f);
    const bz::scene::Camera c = bz::app::camera_for(camera, b);
    if (!bz::scene::camera_problem(c).empty()) __builtin_trap();
}

// One command: its real parser, then what the command would read and write.
using Runner = void (*)(bz::app::Args);

const Runner kCommands[] = {
    [](bz::app::Args a) {
        const auto o = bz::app::parse_render_args(a);
        use_input(o.input);
        use_camera(o.camera);
        use_output("--out", o.out, Out::png, o.overwrite);
        use_output("--mask", o.mask, Out::png, o.overwrite);
    },
    [](bz::app::Args a) {
        const auto o = bz::app::parse_reference_args(a);
        use_input(o.input);
        use_input(o.level);
        if (o.level.empty()) use_camera(o.camera);
        use_output("--mask", o.mask, Out::png, o.overwrite);
    },
    [](bz::app::Args a) {
        const auto o = bz::app::parse_bench_args(a);
        use_input(o.level);
        use_input(o.replay);
        use_output_dir("--out", o.out, o.overwrite);
    },
    [](bz::app::Args a) {
        const auto o = bz::app::parse_difficulty_args(a);
        for (const std::string& l : o.levels) use_input(l);
        use_output("--json", o.json, Out::json, o.overwrite);
    },
    [](bz::app::Args a) {
        const auto o = bz::app::parse_replay_args(a);
        use_input(o.level);
        if (o.record_seconds > 0)
            use_output("--record-demo", o.file, Out::replay, o.overwrite);
        else
            use_input(o.file);
    },
    [](bz::app::Args a) {
        const auto o = bz::app::parse_play_options(static_cast<int>(a.size()), a.data());
        use_input(o.level);
        use_input(o.replay);
        use_output("--record", o.record, Out::replay, false);
    },
    [](bz::app::Args a) {
        const auto o = bz::app::parse_compare_args(a);
        use_input(o.test);
        use_input(o.ref);
    },
    [](bz::app::Args a) {
        for (const std::string_view f : bz::app::parse_check_args(a).files) use_input(f);
    },
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (g_scratch.empty()) make_scratch();
    if (size < 1) return 0;
    const Runner run = kCommands[data[0] % std::size(kCommands)];
    // The rest: words separated by NUL bytes, at most 32 of them.
    std::vector<std::string> words;
    std::string word;
    for (std::size_t i = 1; i < size && words.size() < 32; ++i) {
        if (data[i] == 0) {
            words.push_back(word);
            word.clear();
        } else {
            word += static_cast<char>(data[i]);
        }
    }
    if (words.size() < 32) words.push_back(word);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    try {
        run(bz::app::Args(argv.data(), argv.size()));
    } catch (const bz::app::UsageError& e) {
        check_message(e.what());
    } catch (const bz::UserError& e) {
        check_message(e.what());
    }
    restore_scratch();
    return 0;
}
