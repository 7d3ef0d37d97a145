#!/usr/bin/env python3
"""Checks that README.md, CONTRIBUTING.md and docs/**.md name only things that exist.

Usage: docs_check.py BEAMZONE_BINARY REPO_ROOT SETTINGS_TOML [FILE.md...]

Only text in code (`spans`, fenced and indented blocks) and link targets are read, so prose is
free. What is checked:
  - commands: `beamzone CMD` (or a span that starts with a command name and goes on with a
    flag, `play --edit`) names a command `beamzone --help` lists;
  - flags: every `--flag` of such a command line is in `beamzone CMD --help`; a span that is a
    lone `--flag` must be in some command's help; `--flag a|b|c` alternatives (lower case) must
    each be in that command's help;
  - styles: `--style X`, `style = "X"` and the first column of a table headed "style" name a
    style `render --help` lists;
  - paths: a span that starts with a top-level folder of the repository (src/, docs/, ...) or
    names a source file (*.cpp, *.h, *.glsl, ...) must exist (globs and <placeholders> must
    match something); relative link targets must exist;
  - settings keys: in a sentence about the settings file, a span `key` or `key = value` must be
    a key of SETTINGS_TOML (the file the game writes on first start, every key in it).
Each problem is printed as FILE:LINE: what; the exit status is 1 if there was any.
"""
import fnmatch
import glob
import os
import re
import subprocess
import sys

# Flags that docs name but that belong to other programs (each with where it comes from).
NOT_OUR_FLAGS = {
    "--output-on-failure": "ctest",
    "--prefix": "cmake --install",
    "--gtest_filter": "GoogleTest binaries",
    "--benchmark_format": "Google Benchmark binaries",
    "--benchmark_out": "Google Benchmark binaries",
    "--quick": "tools/test",
    "--seconds": "tools/fuzz (also difficulty --seconds)",
    "--target": "tools/fuzz and cmake --build (also render --target)",
    "--jobs": "tools/fuzz",
    "--bin": "tools/haze, tools/beam_frames",
    "--scene": "tools/haze, tools/beam_frames",
    "--dump-obj": "the vector-monitor renderer of Bernardoni 2018 (docs/sources.md)",
    "--help": "every command",
}
# Programs whose command lines are not ours: their flags are not checked.
OTHER_PROGRAMS = ("ctest", "cmake", "clang-format", "git", "tools/", "build/tests_",
                  "build/bench_", "sudo", "apt", "man ", "mv ", "cd ", "for ", "LP_NUM_THREADS")
TOP_FOLDERS = ("src/", "shaders/", "tests/", "tools/", "levels/", "data/", "docs/", "dist/",
               ".ci/")
SOURCE_EXTENSIONS = (".cpp", ".h", ".glsl", ".vert", ".frag", ".geom", ".comp", ".sh", ".py")
# Paths that belong to other projects or that the reader creates (each with whose it is).
NOT_OUR_PATHS = {
    "src/emu/video/vector.cpp": "MAME",
    "vector.cpp": "MAME",
    "render.cpp": "MAME",
    "levels/mine.toml": "the level docs/levels.md has the reader write",
}
# Files and folders the program writes, named in docs but not in the repository.
GENERATED = ("build/", "build-asan/", "bench-out/", "out/", "screenshots/", "masks/", "diffs/",
             "reference-cache/")


def run(args):
    p = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.stdout


def help_flags(text):
    return set(re.findall(r"(?<![\w-])(--[a-z0-9][a-z0-9-]*)", text))


def code_pieces(text):
    """(line number, code text, sentence it sits in) for every span, block line and link."""
    lines = text.split("\n")
    pieces = []
    in_fence = False
    prev_blank = True
    in_indented = False
    for i, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            in_fence = not in_fence
            continue
        if in_fence:
            pieces.append((i, line, "block", line))
            continue
        if line.startswith("    ") and (prev_blank or in_indented) and not line.lstrip().startswith(("-", "|", "*")):
            in_indented = True
            pieces.append((i, line, "block", line))
            prev_blank = False
            continue
        in_indented = in_indented and line.startswith("    ")
        prev_blank = line.strip() == ""
    # Spans: over paragraphs, since a span or a sentence may cross a line break.
    in_fence = False
    para, start = [], None
    for i, line in enumerate(lines + [""], 1):
        if line.lstrip().startswith("```"):
            in_fence = not in_fence
        if in_fence or line.lstrip().startswith("```") or line.strip() == "" or line.startswith("    ") and not para:
            if para:
                pieces.extend(spans_of(para, start))
            para, start = [], None
            continue
        if start is None:
            start = i
        para.append(line)
    return pieces


def spans_of(para_lines, start):
    text = "\n".join(para_lines)
    out = []
    for m in re.finditer(r"(`+)(.+?)\1", text, flags=re.S):
        line = start + text.count("\n", 0, m.start())
        # The sentence (or table cell) around the span: for the settings-key rule.
        left = max(text.rfind(". ", 0, m.start()), text.rfind("|", 0, m.start()),
                   text.rfind(":", 0, m.start() - 1) if False else -1)
        right_candidates = [x for x in (text.find(". ", m.end()), text.find("|", m.end()))
                            if x != -1]
        right = min(right_candidates) if right_candidates else len(text)
        out.append((line, m.group(2).replace("\n", " ").strip(), "span", text[left + 1:right]))
    for m in re.finditer(r"\]\(([^)\s]+)\)", text):
        line = start + text.count("\n", 0, m.start())
        out.append((line, m.group(1), "link", ""))
    return out


class Checker:
    def __init__(self, binary, root, settings_file):
        self.root = root
        self.problems = []
        self.counts = {"command lines": 0, "flags": 0, "paths": 0, "settings keys": 0, "links": 0}
        top = run([binary, "--help"])
        self.commands = re.findall(r"^  ([a-z]+) ", top, flags=re.M)
        if not self.commands:
            sys.exit("docs_check: `beamzone --help` lists no commands:\n" + top)
        self.help = {c: run([binary, c, "--help"]) for c in self.commands}
        self.flags = {c: help_flags(h) for c, h in self.help.items()}
        self.all_flags = set().union(*self.flags.values())
        # "--style: vector (default), vector-xray, ... or halo (occluded and arcade are the old
        # names ...)": the names, and the old names, which are accepted too.
        m = re.search(r"--style: (.*?)\((\w+)\s+and\s+(\w+)\s+are\s+the\s+old\s+names", self.help["render"],
                      flags=re.S)
        self.styles = set()
        if m:
            names = re.sub(r"\([^)]*\)", "", m.group(1))
            self.styles = set(re.findall(r"[a-z][a-z-]*", names)) - {"or"}
            self.styles |= {m.group(2), m.group(3)}
        # Since the style table (src/scene/style_table.h) the help lists one style a line:
        # "  NAME  help (old name: OLD)" under "--style: ...:".
        t = re.search(r"^--style:[^\n]*:\n((?:  [a-z][a-z-]*  [^\n]*\n?)+)", self.help["render"], flags=re.M)
        if t:
            for sm in re.finditer(r"^  ([a-z][a-z-]*)  [^\n]*?(?:\(old name: ([a-z][a-z-]*)\))?$", t.group(1),
                                  flags=re.M):
                self.styles.add(sm.group(1))
                if sm.group(2):
                    self.styles.add(sm.group(2))
        if not {"vector", "toon", "halo"} <= self.styles:
            sys.exit("docs_check: cannot read the style list from `render --help`")
        self.settings_keys = set()
        for line in open(settings_file, encoding="utf-8"):
            km = re.match(r"\s*#?\s*([a-z_0-9]+)\s*=", line)
            if km:
                self.settings_keys.add(km.group(1))
            tm = re.match(r"\s*\[([a-z_0-9.]+)\]", line)
            if tm:
                self.settings_keys.add(tm.group(1))
        if "volume" not in self.settings_keys:
            sys.exit("docs_check: %s has no settings keys" % settings_file)
        self.tracked = run(["git", "-C", root, "ls-files"]).split("\n")

    def problem(self, where, what):
        self.problems.append("%s: %s" % (where, what))

    # -- commands and flags
    def check_command_line(self, where, code):
        self.counts["command lines"] += 1
        for m in re.finditer(r"(?:^|[\s/(])beamzone\s+([a-z][a-z-]*)", code):
            if m.group(1) not in self.commands:
                self.problem(where, "'beamzone %s': no such command" % m.group(1))
        words = code.split()
        i = 0
        while i < len(words):
            w = words[i].strip("[]()|,;")
            if w.endswith("beamzone") or (i == 0 and w in self.commands):
                cmd = words[i + 1] if w.endswith("beamzone") and i + 1 < len(words) else w
                if cmd in self.commands:
                    j = i + (2 if w.endswith("beamzone") else 1)
                    while j < len(words) and words[j] not in ("|", "&&", ";", "#", ">", "2>"):
                        self.check_flag(where, cmd, words[j], words[j + 1] if j + 1 < len(words) else "")
                        if words[j].startswith("#"):
                            break
                        j += 1
                    i = j
                    continue
            i += 1

    def check_flag(self, where, cmd, word, following):
        m = re.match(r"\[?(--[a-z0-9][a-z0-9-]*)(?:[= ]([^\]\s]*))?", word)
        if not m:
            return
        flag = m.group(1)
        if flag == "--help":
            return
        self.counts["flags"] += 1
        if flag not in self.flags[cmd]:
            self.problem(where, "'%s %s': not in `beamzone %s --help`" % (cmd, flag, cmd))
            return
        value = m.group(2) or following.strip("[]")
        if "|" in value and re.fullmatch(r"[a-z0-9_|-]+", value):
            for alt in value.split("|"):
                if not re.search(r"(?<![\w-])%s(?![\w])" % re.escape(alt), self.help[cmd]):
                    self.problem(where, "'%s %s %s': '%s' is not in `beamzone %s --help`" %
                                 (cmd, flag, value, alt, cmd))
        if flag == "--style" and re.fullmatch(r"[a-z-]+", value or "") and value not in self.styles:
            self.problem(where, "'--style %s': no such style" % value)

    def check_lone_flags(self, where, code):
        for flag in re.findall(r"(?<![\w-])(--[a-z0-9][a-z0-9_-]*)", code):
            self.counts["flags"] += 1
            if flag not in self.all_flags and flag not in NOT_OUR_FLAGS:
                self.problem(where, "'%s': no command has this flag" % flag)

    # -- paths
    def exists(self, path):
        path = path.rstrip(".,;:")
        pattern = re.sub(r"<[^>]*>", "*", path)
        # Upper-case words are placeholders (levels/L.toml, tests/<folder>/NAME_test.cpp).
        pattern = re.sub(r"\b[A-Z][A-Z_]*\b", "*", pattern) if "/" in pattern else pattern
        braces = re.search(r"\{([^}]*)\}", pattern)
        candidates = [pattern]
        if braces:
            candidates = [pattern[:braces.start()] + alt + pattern[braces.end():]
                          for alt in braces.group(1).split(",")]
        for c in candidates:
            c = c.replace("**/", "*").replace("...", "*")
            if not any(ch in c for ch in "*?["):
                if os.path.exists(os.path.join(self.root, c)):
                    continue
                return False
            if not (glob.glob(os.path.join(self.root, c), recursive=True) or
                    fnmatch.filter(self.tracked, c)):
                return False
        return True

    def check_paths(self, where, code):
        for token in re.findall(r"[\w.<>{},*/\-]+", code):
            token = token.strip(".,")
            if ("://" in token or token.startswith(("/", "../")) or token.startswith(GENERATED) or
                    token in NOT_OUR_PATHS):
                continue
            if token.startswith(TOP_FOLDERS) or token in ("CMakeLists.txt", "README.md",
                                                          "CONTRIBUTING.md", ".clang-format"):
                self.counts["paths"] += 1
                if not self.exists(token):
                    self.problem(where, "'%s': no such path in the repository" % token)
            elif token.endswith(SOURCE_EXTENSIONS) and re.fullmatch(r"[\w/.<>*{},-]+", token):
                # A file named without its folder: some tracked file must end with it.
                name = re.sub(r"<[^>]*>", "*", token.split("{")[0] if "{" in token else token)
                if "{" in token:
                    name += "*"
                self.counts["paths"] += 1
                if not (fnmatch.filter(self.tracked, name) or
                        fnmatch.filter(self.tracked, "*/" + name)):
                    self.problem(where, "'%s': no such file in the repository" % token)

    def check_link(self, where, doc, target):
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            return
        path = target.split("#")[0]
        self.counts["links"] += 1
        if not os.path.exists(os.path.normpath(os.path.join(os.path.dirname(doc), path))):
            self.problem(where, "link to '%s': no such file" % target)

    # -- settings keys
    # The ways the docs name a key of the settings file: "`key` in the settings (file)",
    # "the settings file's `key`", "the settings file (`a`, `b`, `c`)", and a TOML line
    # "`key = value`" in a sentence about the settings file.
    SETTINGS_NAMED = [
        r"`([a-z][a-z_0-9]*)`\s+in\s+(?:the\s+)?(?:settings\b|`settings\.toml`)",
        r"settings\s+file's\s+`([a-z][a-z_0-9]*)`",
    ]
    SETTINGS_LIST = r"settings\s+file\s+\(((?:`[a-z][a-z_0-9]*`(?:,\s*|\s+and\s+)?)+)\)"

    def check_settings(self, rel, text):
        def line_of(pos):
            return text.count("\n", 0, pos) + 1
        named = []
        for pattern in self.SETTINGS_NAMED:
            named += [(m.start(), m.group(1)) for m in re.finditer(pattern, text)]
        for m in re.finditer(self.SETTINGS_LIST, text):
            named += [(m.start(), k) for k in re.findall(r"`([^`]*)`", m.group(1))]
        for para in re.finditer(r"(?:[^\n]+\n?)+", text):
            for sentence in re.finditer(r"[^.]+", para.group(0)):
                if not re.search(r"settings\s+(?:file|\.toml)|`settings\.toml`", sentence.group(0)):
                    continue
                for m in re.finditer(r"`([a-z][a-z_0-9]*)\s*=\s*[^`]*`", sentence.group(0)):
                    named.append((para.start() + sentence.start() + m.start(), m.group(1)))
        self.counts["settings keys"] += len(named)
        for pos, key in named:
            if key not in self.settings_keys:
                self.problem("%s:%d" % (rel, line_of(pos)),
                             "'%s': the settings file has no such key" % key)

    def check_style_tables(self, where_prefix, text):
        header = None
        for i, line in enumerate(text.split("\n"), 1):
            if not line.startswith("|"):
                header = None
                continue
            cells = [c.strip() for c in line.strip("|").split("|")]
            if header is None:
                header = cells[0].lower()
                continue
            if header == "style":
                m = re.fullmatch(r"`([^`]*)`", cells[0])
                if m and m.group(1) not in self.styles:
                    self.problem("%s:%d" % (where_prefix, i), "'%s': no such style" % m.group(1))

    def check_file(self, doc):
        text = open(doc, encoding="utf-8").read()
        rel = os.path.relpath(doc, self.root)
        self.check_style_tables(rel, text)
        self.check_settings(rel, text)
        lines = text.split("\n")
        pending = ""
        for line_no, code, kind, sentence in code_pieces(text):
            where = "%s:%d" % (rel, line_no)
            if kind == "link":
                self.check_link(where, doc, code)
                continue
            self.check_paths(where, code)
            if kind == "block":
                # A synopsis goes on over indented lines that start with '['.
                if re.match(r"\s+\[", code) and pending:
                    code = pending + " " + code.strip()
                pending = code if "beamzone" in code else ""
            stripped = code.strip()
            if stripped.startswith(OTHER_PROGRAMS):
                continue
            first = stripped.split(" ")[0] if stripped else ""
            if "beamzone" in stripped or (first in self.commands and " --" in stripped):
                self.check_command_line(where, stripped)
            elif kind == "span":
                self.check_lone_flags(where, stripped)
                sm = re.fullmatch(r'style = "([^"]*)"', stripped)
                if sm and sm.group(1) not in self.styles:
                    self.problem(where, "'%s': no such style" % sm.group(1))


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    binary, root, settings = sys.argv[1:4]
    docs = sys.argv[4:] or ([os.path.join(root, "README.md"), os.path.join(root, "CONTRIBUTING.md")] +
                            sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True)))
    checker = Checker(binary, root, settings)
    for doc in docs:
        if os.path.exists(doc):
            checker.check_file(doc)
    for p in checker.problems:
        print(p)
    print("docs_check: %d files against %d commands, %d styles, %d settings keys; checked %s; "
          "%d problems" % (len(docs), len(checker.commands), len(checker.styles),
                           len(checker.settings_keys),
                           ", ".join("%d %s" % (n, k) for k, n in checker.counts.items()),
                           len(checker.problems)))
    return 1 if checker.problems else 0


if __name__ == "__main__":
    sys.exit(main())
