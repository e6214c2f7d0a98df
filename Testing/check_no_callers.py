"""Every public function the product's headers declare has a caller.

A function nobody calls is dead code a maintainer still reads, documents and keeps
building. This lists the public member functions and the free functions declared in the
tracked headers of Filters/, Haptics/ and ParaViewPlugin/ and fails on any whose name is
used nowhere but in its own declaration and definition: a use is the name as a word in a
tracked C++ source or header, a Python script or a server-manager XML file (comments,
Python docstrings and XML <Documentation> left out). A definition is the name on an
unindented line with only a return type and qualifiers before it (`Class::name(`);
the declaration is the header's own mention. Left out, since a caller of theirs is not
the project's: VTK's macro-generated members (vtkSetMacro and friends), overrides
(`override`/`final`: the base's caller calls them), constructors, destructors, operators
and deleted or defaulted members. Word-level, as check_doc_names.py is: an overload or a
same-named function elsewhere counts as a use (the check may miss a dead name, never flag
a called one). A function kept on purpose with no caller goes into DELIBERATE with why.
Run by ctest as House.NoUncalledPublicFunctions; `--self-test` (ctest
House.NoUncalledPublicFunctionsCanFail) shows that it flags an uncalled function."""
import io
import os
import re
import sys
import tokenize

from check_doc_paths import ROOT, report, tree_files

PRODUCT = ("Filters/", "Haptics/", "ParaViewPlugin/")
CPP = (".h", ".cxx", ".cpp", ".txx")
USES = CPP + (".py", ".xml")
SELF = "Testing/check_no_callers.py"

# Qualified name -> why it stays without a caller in the tree.
DELIBERATE = {
    "vtkChainMailDeformationFilter::AddMarkersConnection":
        "the pipeline form of the markers input (port 2) for VTK programs, as "
        "AddObstacleConnection is for port 1; ParaView connects the port through the XML's "
        "InputProperty and the tests and benchmark give data (SetMarkersData)",
    "vtkMarkerMisfitFilter::SetMarkersConnection":
        "the pipeline form of the markers input (port 1) for VTK programs, as "
        "vtkProbeFilter::SetSourceConnection; ParaView connects the port through the XML's "
        "InputProperty and the tests give data (SetMarkersData)",
}

IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
NOT_A_NAME = {"void", "bool", "char", "int", "long", "short", "unsigned", "signed", "float",
              "double", "auto", "return", "if", "while", "for", "switch", "sizeof", "alignof",
              "decltype", "alignas", "static_assert", "noexcept", "throw", "new", "delete"}


def blank(match):
    """The match as spaces, its newlines kept: offsets and line numbers stay the file's."""
    return re.sub(r"[^\n]", " ", match.group(0))


CPP_COMMENTS = re.compile(r"//[^\n]*|/\*.*?\*/|\"(?:\\.|[^\"\\\n])*\"|'(?:\\.|[^'\\\n])*'", re.S)


def cpp_code(text, strings=False):
    """C++ text without comments (and without string literals when `strings`)."""
    return CPP_COMMENTS.sub(
        lambda m: blank(m) if m.group(0)[0] == "/" or strings else m.group(0), text)


def python_code(text):
    """Python text without comments and docstrings."""
    lines = text.splitlines(True)
    starts = [0]
    for line in lines:
        starts.append(starts[-1] + len(line))
    out = list(text)
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, SyntaxError):
        return text
    previous = tokenize.NEWLINE
    for i, tok in enumerate(tokens):
        following = tokens[i + 1].type if i + 1 < len(tokens) else tokenize.NEWLINE
        docstring = (tok.type == tokenize.STRING and following == tokenize.NEWLINE and
                     previous in (tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT, tokenize.NL))
        if tok.type == tokenize.COMMENT or docstring:
            begin = starts[tok.start[0] - 1] + tok.start[1]
            end = starts[tok.end[0] - 1] + tok.end[1]
            for k in range(begin, end):
                if out[k] != "\n":
                    out[k] = " "
        if tok.type not in (tokenize.COMMENT, tokenize.NL):
            previous = tok.type
    return "".join(out)


def xml_code(text):
    return re.sub(r"<!--.*?-->|<Documentation\b.*?</Documentation>", blank, text, flags=re.S)


def code_of(path, text):
    if path.endswith(".py"):
        return python_code(text)
    if path.endswith(".xml"):
        return xml_code(text)
    return cpp_code(text)


# Macros, blanked before a header is read for declarations: VTK's (vtkSetMacro(...)),
# upper-case ones (export macros, Q_OBJECT, Q_PROPERTY(...)) but Qt's section labels.
MACROS = re.compile(r"\bvtk\w*Macro\s*\((?:[^()]|\([^()]*\))*\)|"
                    r"\b(?!Q_SIGNALS\b|Q_SLOTS\b)[A-Z][A-Z0-9_]{2,}\b(?:\s*\((?:[^()]|\([^()]*\))*\))?")
PREPROCESSOR = re.compile(r"^[ \t]*#(?:[^\n]*\\\n)*[^\n]*", re.M)
ACCESS = re.compile(r"^\s*(public|protected|private|signals|Q_SIGNALS)\s*(?:slots|Q_SLOTS)?\s*:(?!:)")
SCOPE = re.compile(r"^\s*(?:template\s*<[^{;]*>\s*)?(class|struct|union|namespace|enum|extern)\b"
                   r"(?:\s+(?:class|struct)\b)?(?:\s*alignas\s*\([^)]*\))?\s*(\w*)")


def strip_template(text):
    """The statement without a leading template<...> (nested angle brackets balanced)."""
    m = re.match(r"\s*template\s*<", text)
    if not m:
        return text
    depth, i = 1, m.end()
    while i < len(text) and depth:
        depth += {"<": 1, ">": -1}.get(text[i], 0)
        i += 1
    return strip_template(text[i:])


def function_name(text, enclosing):
    """(name, offset in text) when the statement declares a function, else None."""
    body = strip_template(text)
    shift = len(text) - len(body)
    if re.search(r"\boperator\b|^\s*(typedef|using|friend|static_assert)\b", body):
        return None
    paren = body.find("(")
    if paren < 0 or "=" in body[:paren]:
        return None
    before = body[:paren]
    m = re.search(r"(~?)([A-Za-z_]\w*)\s*$", before)
    if not m or m.group(1) or m.group(2) in NOT_A_NAME or m.group(2) == enclosing:
        return None
    prefix = before[:m.start()].strip()
    if not re.search(r"\w", prefix) or re.search(r"[;{}()]", prefix):
        return None  # a macro call or a constructor without a return type
    after = body[paren:]
    if re.search(r"\b(override|final)\b|=\s*(delete|default)\b", after):
        return None
    return m.group(2), shift + m.start(2)


def declarations(text):
    """(qualified name, name, offset) of the public functions a header declares."""
    code = cpp_code(text, strings=True)
    code = PREPROCESSOR.sub(blank, code)
    code = MACROS.sub(blank, code)
    stack = []  # [kind, name, public]
    start = 0
    found = []
    for m in re.finditer(r"[{};]", code):
        char, pos = m.group(0), m.start()
        text_start, statement = start, code[start:pos]
        start = pos + 1
        if char == "}":
            if stack:
                stack.pop()
            continue
        if not all(kind in ("namespace", "class") for kind, _, _ in stack):
            if char == "{":
                stack.append(["body", "", False])
            continue
        # Access labels (class scope), then what the statement is.
        while stack and stack[-1][0] == "class":
            a = ACCESS.match(statement)
            if not a:
                break
            stack[-1][2] = a.group(1) in ("public", "signals", "Q_SIGNALS")
            text_start += a.end()
            statement = statement[a.end():]
        scope = SCOPE.match(statement) if char == "{" else None
        if scope and "(" not in statement.split(":")[0]:
            kind = scope.group(1)
            if kind in ("class", "struct", "union"):
                stack.append(["class", scope.group(2), kind != "class"])
            elif kind == "enum":
                stack.append(["enum", "", False])
            else:
                stack.append(["namespace", scope.group(2), True])
            continue
        if all(public for _, _, public in stack):
            enclosing = stack[-1][1] if stack and stack[-1][0] == "class" else None
            named = function_name(statement, enclosing)
            if named:
                qualified = "::".join([n for kind, n, _ in stack if kind == "class" and n] +
                                      [named[0]])
                found.append((qualified, named[0], text_start + named[1]))
        if char == "{":
            stack.append(["body", "", False])
    return found


def definitions(code, names):
    """Offsets of the names defined on an unindented line (`Type Class::name(`)."""
    out = set()
    for m in re.finditer(r"^[A-Za-z_~][^\n]*", code, re.M):
        line = m.group(0)
        for w in IDENT.finditer(line):
            if w.group(0) in names and re.match(r"\s*\(", line[w.end():]) and \
                    re.fullmatch(r"[\w\s:<>*&,~]*", line[:w.start()]) and \
                    not re.search(r"\breturn\b", line[:w.start()]):
                out.add(m.start() + w.start())
    return out


def uncalled(files):
    """files: {path: text}. (path, line, qualified) of each declared name without a use."""
    declared = []
    for path, text in files.items():
        if path.startswith(PRODUCT) and path.endswith(".h"):
            declared += [(path, q, n, o) for q, n, o in declarations(text)]
    names = {n for _, _, n, _ in declared}
    skip = {(p, o) for p, _, _, o in declared}
    used = set()
    for path, text in files.items():
        if not path.endswith(USES) or path == SELF:
            continue  # this script's allow-list names are no calls
        code = code_of(path, text)
        if path.endswith(CPP):
            skip |= {(path, o) for o in definitions(code, names)}
        for w in IDENT.finditer(code):
            if w.group(0) in names and (path, w.start()) not in skip:
                used.add(w.group(0))
    out = []
    for path, qualified, name, offset in declared:
        if name not in used and qualified not in DELIBERATE:
            out.append((path, files[path].count("\n", 0, offset) + 1, qualified))
    return sorted(set(out))


def self_test():
    """The check flags a public function nobody calls, and only it."""
    files = {
        "Filters/X/vtkSample.h": "class vtkSample : public vtkObject\n{\npublic:\n"
        "  vtkSetMacro(Size, int);\n  int Used();\n  void Dead(int n);\n"
        "  void RequestData() override;\nprivate:\n  void Hidden();\n};\n"
        "double free_dead(double x);\ndouble free_used(double x);\n",
        "Filters/X/vtkSample.cxx": "int vtkSample::Used()\n{\n  return 1;\n}\n"
        "void vtkSample::Dead(int n)\n{\n  // Dead(n) in a comment is no call\n}\n"
        "double free_dead(double x)\n{\n  return x;\n}\n"
        "double free_used(double x)\n{\n  return x;\n}\n",
        "Testing/X/test.py": "s.Used()  # free_dead() only in a comment\n",
        "Testing/X/test.cxx": "int main()\n{\n  return free_used(1.0) > 0;\n}\n",
    }
    got = [q for _, _, q in uncalled(files)]
    want = ["free_dead", "vtkSample::Dead"]
    if sorted(got) != want:
        print("self-test: flagged %s, expected %s" % (got, want))
        return 1
    print("self-test: flagged %s, as expected" % got)
    return 0


def main(argv):
    if "--self-test" in argv:
        return self_test()
    files = {}
    for f in tree_files():
        f = f.replace(os.sep, "/")
        if f.endswith(USES):
            with open(os.path.join(ROOT, f), encoding="utf-8", errors="replace") as h:
                files[f] = h.read()
    broken = ["%s:%d: %s" % found for found in uncalled(files)]
    return report(broken, "public function(s) declared in a product header with no caller")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
