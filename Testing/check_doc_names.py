"""Every code name the docs give in backticks is a name in the tree or in the platform.

README.md and docs/*.md name classes, functions, properties, arrays and tests as
`ChainMailDeformer::set_threads`, `priority_band()`, `NumberOfThreads`, `VerticalMisfit`
or `Core.MarkerMisfit.SummaryCountsOnlyTheInsideMarkers`; a name renamed or removed
without its mention leaves the reader a dead end. A backticked word (no "/", no space)
counts as a code name when it is identifiers joined by "::" or "." (optionally with
"()") and looks like code: it holds "::" or "()", an inner "_" (not a one-letter math
subscript such as `w_max`), a lower-to-upper case step (CamelCase) or starts with vtk/pq.
It resolves when its last identifier is a word of a tracked source, build or test file
(docs excluded) or a file's stem, when the whole word is a test ctest lists, or when it is
a word of the platform's VTK/ParaView headers (the folders given as arguments after the
build folder). docs/changelog.md is left out: it says what was true before.
Run by ctest as Docs.BacktickedNamesExist: check_doc_names.py BUILD_DIR [INCLUDE_DIR...]"""
import os
import re
import subprocess
import sys

from check_doc_paths import ROOT, backticked_words, report, tree_files

SOURCE = (".h", ".cxx", ".cpp", ".py", ".xml", ".cmake", ".txt", ".json", ".in", ".sh",
          ".module", ".plugin", ".ui", ".qrc")
NAME = re.compile(r"^~?[A-Za-z_][A-Za-z0-9_]*(?:(?:::|\.)~?[A-Za-z_][A-Za-z0-9_]*)*(?:\(\))?$")
MATH = re.compile(r"^[A-Za-z]_[A-Za-z0-9]+$")
HISTORY = {"docs/changelog.md"}


def looks_like_code(word):
    base = word[:-2] if word.endswith("()") else word
    if MATH.match(base):
        return False
    return ("::" in base or word.endswith("()") or "_" in base.strip("_")
            or re.search(r"[a-z][A-Z]", base) is not None or base.startswith(("vtk", "pq")))


def words_of(paths):
    words = set()
    for path in paths:
        try:
            with open(path, encoding="utf-8", errors="replace") as f:
                words.update(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", f.read()))
        except OSError:
            pass
    return words


def main(argv):
    build = argv[1] if len(argv) > 1 else None
    files = [f.replace(os.sep, "/") for f in tree_files()]
    known = words_of(os.path.join(ROOT, f) for f in files
                     if f.endswith(SOURCE) or os.path.basename(f) == "CMakeLists.txt")
    known |= {os.path.splitext(os.path.basename(f))[0] for f in files}
    for include in sorted({os.path.normpath(i) for i in argv[2:] if i}):
        if os.path.isdir(include):
            known |= words_of(os.path.join(include, n) for n in os.listdir(include)
                              if n.endswith((".h", ".txx")))
    tests = set()
    if build:
        out = subprocess.run(["ctest", "-N"], cwd=build, capture_output=True, text=True)
        tests = set(re.findall(r"Test\s+#\d+:\s+(\S+)", out.stdout))
    broken = []
    for page, number, word in backticked_words():
        if page in HISTORY or "/" in word or not NAME.match(word) or not looks_like_code(word):
            continue
        if word in tests or any(t.startswith(word + ".") for t in tests):
            continue
        last = re.split(r"::|\.", word[:-2] if word.endswith("()") else word)[-1].lstrip("~")
        if last not in known:
            broken.append("%s:%d: `%s`" % (page, number, word))
    return report(broken, "backticked code name(s) found neither in the tree nor in VTK/ParaView")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
