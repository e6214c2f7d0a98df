"""Every file path the docs name in backticks is a file or folder of the tree.

README.md and docs/*.md name sources, headers, scripts and data as `Filters/IO/...`,
`link_projection.h` or `Testing/GUI/TestHook`; a file renamed or removed without its
mention leaves the reader a dead end. A backticked word counts as a path when it has no
space and either holds a "/" or ends in a source, script or data extension; it resolves
when it names a file or folder from the repository root or from the page's folder, when
it is the end of such a path (`geoshaping/haptics/proxy.h`, `ContactPatch.h`), when it
is such a path without its extension or its configured `.in`, or, with a "*", when its
pattern matches one. Run by ctest as Docs.BacktickedPathsExist."""
import fnmatch
import os
import re
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

EXTENSIONS = (".h", ".cxx", ".cpp", ".py", ".xml", ".md", ".cmake", ".txt", ".json", ".ts",
              ".npz", ".npy", ".png", ".sh", ".yml", ".yaml", ".pvsm", ".in")
# Output files, options and the like that look like paths but are not the tree's.
NOT_IN_TREE = re.compile(r"^(/|~|\$|\.\./|build/|https?:|-|<|BM_)|\.\.\.|[<>{}=()\[\]:;,'\"]")


def tree_files():
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True)
    if out.returncode == 0 and out.stdout:
        return out.stdout.split()
    files = []
    for folder, dirs, names in os.walk(ROOT):
        dirs[:] = [d for d in dirs if d not in (".git", "build")]
        files += [os.path.relpath(os.path.join(folder, n), ROOT) for n in names]
    return files


def backticked_words():
    """(page, line number, word) for every backticked word without a space of README.md and
    docs/*.md, outside code blocks (commands, not names)."""
    pages = ["README.md"] + sorted(
        os.path.join("docs", n) for n in os.listdir(os.path.join(ROOT, "docs")) if n.endswith(".md"))
    for page in pages:
        text = open(os.path.join(ROOT, page), encoding="utf-8").read()
        # Blank the code blocks' lines, so that line numbers stay the page's own.
        text = re.sub(r"```.*?```", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
        for number, line in enumerate(text.splitlines(), 1):
            for word in re.findall(r"`([^`\s]+)`", line):
                yield page, number, word


def main():
    files = [f.replace(os.sep, "/") for f in tree_files()]
    folders = {"/".join(f.split("/")[:i]) for f in files for i in range(1, f.count("/") + 1)}
    entries = set(files) | folders
    folder_names = {f.split("/")[-1] for f in folders}
    # `Filters/IO/vtkDEMProjection`, and a file configured from its `.in`.
    stems = {os.path.splitext(f)[0] for f in files}

    def resolves(path, page_folder):
        path = path.rstrip("/")
        if path.startswith("./"):
            path = path[2:]
        candidates = [path, os.path.normpath(os.path.join(page_folder, path)).replace(os.sep, "/")]
        if "*" in path:
            return any(fnmatch.fnmatch(e, "*" + path.lstrip("*")) or fnmatch.fnmatch(e, c)
                       for e in entries for c in candidates)
        if any(c in entries or c in stems for c in candidates):
            return True
        return any(e.endswith("/" + path) for e in entries | stems)

    broken = []
    for page, number, word in backticked_words():
        word = word.split("#")[0]
        if not word or NOT_IN_TREE.search(word):
            continue
        if word.startswith(".") and "/" not in word:
            continue  # an extension: `.npz`
        if not word.endswith(EXTENSIONS):
            # Without an extension, a path only if it starts in a folder of the
            # tree (`Testing/GUI/TestHook`; not `workspace_min/max`).
            if "/" not in word or word.split("/")[0] not in folder_names:
                continue
        if not resolves(word, os.path.dirname(page)):
            broken.append("%s:%d: `%s`" % (page, number, word))
    return report(broken, "backticked path(s) that name nothing in the tree")


def report(broken, what):
    """Prints each broken mention and their count; the exit code (1 when any)."""
    for b in broken:
        print(b)
    print("%d %s" % (len(broken), what))
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
