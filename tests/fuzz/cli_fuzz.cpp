// libFuzzer target for the command line: random argument vectors for every command, parsed
// with the parsers the commands share (ArgCursor, the number, vector, size and style parsers,
// the camera options and their checks) against a table of each command's options, and every
// path they name pushed through the one output writer and the one input reader in a scratch
// folder full of hostile entries (a FIFO, a folder, a foreign file, links to an input, a
// read-only folder). Never a crash, a sanitizer report or a hang (a FIFO opened for reading
// blocks; libFuzzer's -timeout catches it); every message is printable (no raw control byte:
// untrusted text is escaped where it is inserted) and bounded; the inputs, the FIFO and the
// folder are never replaced.
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
#include "app/commands/cli_args.h"
#include "core/error.h"
#include "core/io/file_io.h"
#include "core/io/output_path.h"
#include "core/text/printable.h"
#include "scene/camera_check.h"

namespace fs = std::filesystem;

namespace {

enum class Value {
    none,
    integer,
    number,
    vec3,
    size,
    style,
    text,
    out_png,
    out_json,
    out_replay,
    out_dir,
    in_file
};

struct Option {
    std::string_view name;
    Value value;
    int lo = 0, hi = 0;  // integer range
};

struct Command {
    std::string_view name;
    bool camera;  // takes the shared camera options
    std::vector<Option> options;
};

// Each command's options as its parser knows them (kUsage of src/app/commands/cmd_*.cpp).
const std::vector<Command>& commands() {
    static const std::vector<Command> table = {
        {"render",
         true,
         {{"--preset", Value::text},
          {"--line-method", Value::text},
          {"--color", Value::vec3},
          {"--out", Value::out_png},
          {"--mask", Value::out_png},
          {"--repeat", Value::integer, 1, 100000},
          {"--copies", Value::integer, 1, 10000},
          {"--beam", Value::text},
          {"--lit-share", Value::none},
          {"--overwrite", Value::none},
          {"--style", Value::style},
          {"--no-smoothing", Value::none},
          {"--one-sided", Value::none},
          {"--shading", Value::text}}},
        {"reference",
         true,
         {{"--level", Value::in_file},
          {"--time", Value::number},
          {"--crease", Value::number},
          {"--mask", Value::out_png},
          {"--out", Value::out_png},
          {"--overwrite", Value::none},
          {"--style", Value::style}}},
        {"bench",
         false,
         {{"--frames", Value::integer, 1, 1000000},
          {"--warmup", Value::integer, 0, 100000},
          {"--size", Value::size},
          {"--preset", Value::text},
          {"--style", Value::style},
          {"--line-method", Value::text},
          {"--sweep", Value::none},
          {"--scaling", Value::none},
          {"--accuracy", Value::none},
          {"--beam", Value::text},
          {"--no-phosphor", Value::none},
          {"--models-dir", Value::text},
          {"--model", Value::in_file},
          {"--out", Value::out_dir},
          {"--replay", Value::in_file},
          {"--samples", Value::integer, 1, 1000},
          {"--rounds", Value::integer, 1, 1000},
          {"--timing", Value::text},
          {"--overwrite", Value::none}}},
        {"difficulty",
         false,
         {{"--seeds", Value::integer, 1, 10000},
          {"--seconds", Value::number},
          {"--difficulty", Value::text},
          {"--json", Value::out_json},
          {"--overwrite", Value::none}}},
        {"replay",
         false,
         {{"--verify", Value::none},
          {"--inputs-only", Value::none},
          {"--level", Value::in_file},
          {"--record-demo", Value::integer, 1, 36000},
          {"--seed", Value::integer, 0, 2147483647},
          {"--difficulty", Value::text},
          {"--overwrite", Value::none}}},
        {"play",
         false,
         {{"--record", Value::out_replay},
          {"--replay", Value::in_file},
          {"--size", Value::size},
          {"--frames", Value::integer, 1, 100000000},
          {"--seed", Value::integer, 0, 2147483647},
          {"--style", Value::style},
          {"--difficulty", Value::text},
          {"--headless-test", Value::none}}},
        {"compare", false, {{"--tol", Value::integer, 0, 64}}},
        {"check", false, {{"--quiet", Value::none}, {"-q", Value::none}}},
    };
    return table;
}

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

void use_output(std::string_view option, std::string_view word, Value kind, bool overwrite) {
    const fs::path out = confine(word);
    const fs::path inputs[] = {g_scratch / "in.toml"};
    if (kind == Value::out_dir) {
        constexpr std::string_view subs[] = {"masks"};
        bz::check_output_dir(option, out, inputs, subs, overwrite);
        return;
    }
    const bz::OutputKind& k = kind == Value::out_png    ? bz::kPngOutput
                              : kind == Value::out_json ? bz::kJsonOutput
                                                        : bz::kReplayOutput;
    bz::check_output_file(option, out, k, inputs, overwrite);
    bz::write_file_atomic(out, std::string(k.magic) + "written by the fuzzer\n");
}

void run(const Command& cmd, std::vector<char*>& argv) {
    bz::app::ArgCursor cur(static_cast<int>(argv.size()), argv.data());
    bz::app::CameraArgs camera;
    std::vector<std::pair<std::string_view, std::pair<std::string_view, Value>>> outputs;
    bool overwrite = false;
    while (!cur.done()) {
        const std::string_view a = cur.next();
        if (cmd.camera && bz::app::parse_camera_option(a, cur, camera)) continue;
        const Option* opt = nullptr;
        for (const Option& o : cmd.options)
            if (o.name == a) opt = &o;
        if (!opt) {
            if (!a.empty() && a[0] == '-')
                throw bz::app::UsageError("unknown option " + bz::printable(a));
            (void)bz::read_file(confine(a), 1u << 16);  // a positional input
            continue;
        }
        switch (opt->value) {
            case Value::none:
                if (a == "--overwrite") overwrite = true;
                break;
            case Value::integer:
                bz::app::parse_int(a, cur.value(a), opt->lo, opt->hi);
                break;
            case Value::number:
                bz::app::parse_number(a, cur.value(a));
                break;
            case Value::vec3:
                bz::app::parse_vec3(a, cur.value(a));
                break;
            case Value::size:
                bz::app::parse_size(a, cur.value(a));
                break;
            case Value::style:
                bz::app::parse_style(a, cur.value(a));
                break;
            case Value::text:
                check_message(bz::printable(cur.value(a)));
                break;
            case Value::in_file:
                (void)bz::read_file(confine(cur.value(a)), 1u << 16);
                break;
            default:
                outputs.push_back({a, {cur.value(a), opt->value}});
        }
    }
    if (cmd.camera) {
        bz::app::validate_camera(camera);
        bz::geo::Bounds b;
        b.min = glm::vec3(-1.0f);
        b.max = glm::vec3(1.0f);
        const bz::scene::Camera c = bz::app::camera_for(camera, b);
        if (!bz::scene::camera_problem(c).empty()) __builtin_trap();  // camera_for let it pass
    }
    for (const auto& [option, target] : outputs)
        use_output(option, target.first, target.second, overwrite);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (g_scratch.empty()) make_scratch();
    if (size < 1) return 0;
    const auto& table = commands();
    const Command& cmd = table[data[0] % table.size()];
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
        run(cmd, argv);
    } catch (const bz::app::UsageError& e) {
        check_message(e.what());
    } catch (const bz::UserError& e) {
        check_message(e.what());
    }
    restore_scratch();
    return 0;
}
