#!/usr/bin/env python3
"""The source layout rules of issue 22, checked on the files under src/.

Issue 22: "No folder of src/ holds more than 25 C files; trace.c is under 500
lines; no function over 100 lines; no *_internal.h crosses a folder; no
include circle spans two folders." Small folders, files and functions are
read and reviewed whole; a folder's internal header is that folder's business;
and folders that include each other in a circle are one folder in fact, which
can be neither understood nor built and tested alone.

Scope: every .c and .h file under src/ (tests/, bench/ and fuzz/ may include
internal headers to test internals and are not checked). A *folder* is one
directory: src/trace and a src/trace/exact below it are two folders, each
counted and checked on its own.

The rules, precisely:

 1. No folder holds more than 25 .c files (the files directly in it; a
    subfolder's files are the subfolder's).
 2. src/trace/trace.c has fewer than 500 lines (as wc -l counts, plus an
    unterminated last line). A missing trace.c fails too: the rule names the
    file, and a move should update this script.
 3. No C function is longer than 100 lines. A function's length is the number
    of lines from the first line of its definition (the return type and the
    specifiers, e.g. the line of "static int" above "name(...)") to the line
    of its closing brace, both included: the definition as it reads, blank and
    comment lines inside included, the comment above it not. Functions in
    headers (static inline) count too. Found by a small parser: comments and
    string and character literals are blanked, preprocessor lines dropped
    (both branches of an #if are read), braces counted at file scope; a "{"
    at file scope opens a function when the text before it, since the last
    ";" or function's "}" at file scope, ends in ")" and holds no "="
    outside parentheses and brackets (so not a struct, enum or union body
    and not a table's or compound literal's initializer). The name is the
    identifier before the parameters' "(". On the tree at the start of issue 22
    it found the 1,466 functions Universal Ctags found there, with the same
    names and last lines (1,484 both, after the move).
 4. No *_internal.h header is included from a file of another folder. An
    #include is resolved as the build resolves it (CMakeLists.txt: the
    library's objects and the command's are built with `include` and `src` as
    include directories): "x.h" first beside the including file, then under
    include/ and src/; <x.h> under include/ and src/ only, else it is a system
    header and ignored. Commented-out #include lines are not read; #if
    conditions are not evaluated. The page's generated source (BUILD/generated/plot/
    web_assets_data.c) lies outside src/ and is not checked; the build adds no
    include directory for it.
 5. No include circle spans two folders. The folder graph has an edge A -> B
    when a file of folder A includes a header of folder B (A != B); the
    public headers under include/ belong to no folder of src/ and are left
    out. Every circle of folders in it is a violation. The finer file graph
    (file -> file for every #include resolved under src/) is checked too: a
    circle of files that spans two folders is a violation. Each circle is
    printed with the #include lines that make its edges.

usage: check_layout.py [--summary] [SOURCE_DIR]
  SOURCE_DIR  the project's top directory (default: the one above tests/)
  --summary   print, per folder, its .c files, its lines (.c and .h) and the
              folders it includes, as a Markdown table (docs), and exit 0
Exit status: 0 when every rule holds, 1 when one is broken, 2 on a usage
error or a file the parser cannot read (unbalanced braces).
"""

import os
import re
import sys
from collections import defaultdict, namedtuple

MAX_C_FILES = 25
TRACE_C = "src/trace/trace.c"
MAX_TRACE_C_LINES = 499
MAX_FUNCTION_LINES = 100
# the include directories of the library's and the command's targets
# (target_include_directories in CMakeLists.txt), relative to SOURCE_DIR
INCLUDE_DIRS = ("include", "src")
INTERNAL_SUFFIX = "_internal.h"
MAX_CYCLES_PRINTED = 50

Include = namedtuple("Include", "file line text target")  # target: repo path or None
Function = namedtuple("Function", "file name first last")


class ParseError(Exception):
    pass


# ---------------------------------------------------------------- the files

def source_files(root):
    """The .c and .h files under src/, as paths relative to root, sorted."""
    found = []
    for top, dirs, files in os.walk(os.path.join(root, "src")):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        for name in files:
            if name.endswith((".c", ".h")):
                found.append(os.path.relpath(os.path.join(top, name), root))
    return sorted(p.replace(os.sep, "/") for p in found)


def folder_of(path):
    """The folder of a repository path: 'src/trace/march.c' -> 'src/trace'."""
    return path.rsplit("/", 1)[0]


def read_text(root, path):
    with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
        return f.read()


def count_lines(text):
    return len(text.splitlines())


# ------------------------------------------------------------ C lexing

def blank_comments_and_literals(text, keep_literals=False):
    """The text with comments (and, unless keep_literals, the contents of
    string and character literals) replaced by spaces; newlines are kept, so
    line numbers stay right."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        two = text[i:i + 2]
        if two == "//":
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif two == "/*":
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = end_of_literal(text, i)
            body = text[i + 1:j - 1]
            if not keep_literals:
                body = re.sub(r"[^\n]", " ", body)
            out.append(c + body + c)
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def end_of_literal(text, start):
    """The index just past the string or character literal at start."""
    quote = text[start]
    i = start + 1
    while i < len(text):
        if text[i] == "\\":
            i += 2
        elif text[i] == quote or text[i] == "\n":
            return i + 1
        else:
            i += 1
    return len(text)


def drop_preprocessor(text):
    """Lines of preprocessor directives (with their continuations) blanked."""
    lines = text.split("\n")
    in_directive = False
    for k, line in enumerate(lines):
        if in_directive or line.lstrip().startswith("#"):
            in_directive = line.rstrip().endswith("\\")
            lines[k] = ""
    return "\n".join(lines)


# ------------------------------------------------------------ functions

def find_functions(path, text):
    """Every function definition of a C file, as Function records."""
    code = drop_preprocessor(blank_comments_and_literals(text))
    line_starts = [0] + [m.end() for m in re.finditer("\n", code)]

    def line_of(pos):
        lo, hi = 0, len(line_starts) - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if line_starts[mid] <= pos:
                lo = mid
            else:
                hi = mid - 1
        return lo + 1

    functions = []
    head_start = 0  # where the text since the last ';' or '}' at file scope begins
    i = 0
    while i < len(code):
        c = code[i]
        if c == ";":
            head_start = i + 1
        elif c == "}":
            raise ParseError("%s:%d: '}' at file scope" % (path, line_of(i)))
        elif c == "{":
            close = matching_brace(code, i, path, line_of)
            head = code[head_start:i]
            if is_function_head(head):
                first = head_start + len(head) - len(head.lstrip())
                functions.append(Function(path, function_name(head),
                                          line_of(first), line_of(close)))
                head_start = close + 1
            i = close  # a struct's or table's body: its ';' follows
        i += 1
    return functions


def matching_brace(code, open_pos, path, line_of):
    depth = 0
    for j in range(open_pos, len(code)):
        if code[j] == "{":
            depth += 1
        elif code[j] == "}":
            depth -= 1
            if depth == 0:
                return j
    raise ParseError("%s:%d: '{' never closed" % (path, line_of(open_pos)))


def is_function_head(head):
    """A file-scope '{' after this text opens a function body: the text ends
    in the parameters' ')' and assigns nothing (no initializer)."""
    stripped = head.rstrip()
    if not stripped.endswith(")"):
        return False
    depth = 0
    for c in stripped:
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c == "=" and depth == 0:
            return False
    return True


def function_name(head):
    """The identifier before the '(' of the last parenthesised group."""
    stripped = head.rstrip()
    depth = 0
    for k in range(len(stripped) - 1, -1, -1):
        if stripped[k] == ")":
            depth += 1
        elif stripped[k] == "(":
            depth -= 1
            if depth == 0:
                m = re.search(r"([A-Za-z_]\w*)\s*$", stripped[:k])
                return m.group(1) if m else "?"
    return "?"


# ------------------------------------------------------------- includes

INCLUDE_RE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*([<"])([^">\n]+)[">]', re.M)


def find_includes(root, path, text):
    """The #include lines of a file, each resolved to a repository path (or
    None: a system header, or one the build finds nowhere in the tree)."""
    code = blank_comments_and_literals(text, keep_literals=True)
    result = []
    for m in INCLUDE_RE.finditer(code):
        line = code.count("\n", 0, m.start()) + 1
        target = resolve_include(root, path, m.group(2), m.group(1) == '"')
        result.append(Include(path, line, m.group(0).strip(), target))
    return result


def resolve_include(root, path, name, quoted):
    """As the compiler does: "x" beside the including file first, then the
    include directories in order; <x> the include directories only."""
    dirs = ([folder_of(path)] if quoted else []) + list(INCLUDE_DIRS)
    for d in dirs:
        candidate = os.path.normpath(os.path.join(d, name)).replace(os.sep, "/")
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def in_src(path):
    return path is not None and path.startswith("src/")


# -------------------------------------------------------------- the rules
# Each rule returns a list of lines describing its violations (empty: holds).

def rule_crowded_folders(files):
    per_folder = c_files_per_folder(files)
    return ["%s: %d .c files (at most %d)" % (folder, n, MAX_C_FILES)
            for folder, n in sorted(per_folder.items()) if n > MAX_C_FILES]


def c_files_per_folder(files):
    counts = defaultdict(int)
    for f in files:
        counts[folder_of(f)] += f.endswith(".c")
    return counts


def rule_trace_c(root):
    if not os.path.isfile(os.path.join(root, TRACE_C)):
        return ["%s: not found (the rule names this file: update %s if it moved)"
                % (TRACE_C, os.path.basename(__file__))]
    n = count_lines(read_text(root, TRACE_C))
    if n > MAX_TRACE_C_LINES:
        return ["%s: %d lines (under %d wanted)" % (TRACE_C, n, MAX_TRACE_C_LINES + 1)]
    return []


def rule_long_functions(functions):
    long_ones = [f for f in functions if f.last - f.first + 1 > MAX_FUNCTION_LINES]
    long_ones.sort(key=lambda f: (f.first - f.last, f.file, f.first))
    return ["%s:%d: %s: %d lines (%d-%d)" % (f.file, f.first, f.name,
                                             f.last - f.first + 1, f.first, f.last)
            for f in long_ones]


def rule_internal_headers(includes):
    out = []
    for inc in includes:
        t = inc.target
        if (in_src(t) and t.endswith(INTERNAL_SUFFIX)
                and folder_of(t) != folder_of(inc.file)):
            out.append("%s:%d: %s -> %s (internal to %s)"
                       % (inc.file, inc.line, inc.text, t, folder_of(t)))
    return out


def rule_include_circles(includes):
    edges = folder_edges(includes)
    out = []
    cycles = simple_cycles({a: set(bs) for a, bs in edges.items()})
    for cycle in cycles[:MAX_CYCLES_PRINTED]:
        out.append("folder circle: " + " -> ".join(cycle + [cycle[0]]))
    if len(cycles) > MAX_CYCLES_PRINTED:
        out.append("... and %d more folder circles" % (len(cycles) - MAX_CYCLES_PRINTED))
    in_cycles = {(c[k], c[(k + 1) % len(c)]) for c in cycles for k in range(len(c))}
    if in_cycles:
        out.append("the includes that make these circles' edges:")
    for a, b in sorted(in_cycles):
        out.append("  %s -> %s:" % (a, b))
        out.extend("    %s:%d: %s" % (i.file, i.line, i.text) for i in edges[a][b])
    out.extend(file_circles(includes))
    return out


def folder_edges(includes):
    """edges[A][B]: the includes by which a file of folder A includes a
    header of folder B (A != B; headers under include/ left out)."""
    edges = defaultdict(lambda: defaultdict(list))
    for inc in includes:
        if in_src(inc.target):
            a, b = folder_of(inc.file), folder_of(inc.target)
            if a != b:
                edges[a][b].append(inc)
    return edges


def file_circles(includes):
    """Circles of files, include by include, that span two folders."""
    graph = defaultdict(set)
    lines = {}
    for inc in includes:
        if in_src(inc.target):
            graph[inc.file].add(inc.target)
            lines.setdefault((inc.file, inc.target), inc)
    out = []
    for component in strongly_connected(graph):
        if len({folder_of(f) for f in component}) < 2:
            continue
        cycle = shortest_cycle(graph, component)
        out.append("file circle across folders: " + " -> ".join(cycle + [cycle[0]]))
        for k, f in enumerate(cycle):
            inc = lines[(f, cycle[(k + 1) % len(cycle)])]
            out.append("    %s:%d: %s" % (inc.file, inc.line, inc.text))
    return out


# ------------------------------------------------------------- graphs

def simple_cycles(graph):
    """Every elementary circle of a small directed graph, each listed once,
    starting from its smallest node."""
    nodes = sorted(set(graph) | {b for bs in graph.values() for b in bs})
    cycles = []

    def walk(start, node, path, seen):
        for nxt in sorted(graph.get(node, ())):
            if nxt == start:
                cycles.append(list(path))
            elif nxt > start and nxt not in seen:
                seen.add(nxt)
                path.append(nxt)
                walk(start, nxt, path, seen)
                path.pop()
                seen.discard(nxt)

    for s in nodes:
        walk(s, s, [s], {s})
    return cycles


def strongly_connected(graph):
    """Tarjan's strongly connected components (iterative), those of two or
    more nodes."""
    index, low, on_stack, stack, comps = {}, {}, set(), [], []
    counter = [0]
    nodes = sorted(set(graph) | {b for bs in graph.values() for b in bs})
    for root in nodes:
        if root in index:
            continue
        work = [(root, iter(sorted(graph.get(root, ()))))]
        visit(root, index, low, counter, stack, on_stack)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is None:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    comp = pop_component(node, stack, on_stack)
                    if len(comp) > 1:
                        comps.append(sorted(comp))
            elif child not in index:
                visit(child, index, low, counter, stack, on_stack)
                work.append((child, iter(sorted(graph.get(child, ())))))
            elif child in on_stack:
                low[node] = min(low[node], index[child])
    return comps


def visit(node, index, low, counter, stack, on_stack):
    index[node] = low[node] = counter[0]
    counter[0] += 1
    stack.append(node)
    on_stack.add(node)


def pop_component(node, stack, on_stack):
    comp = []
    while True:
        top = stack.pop()
        on_stack.discard(top)
        comp.append(top)
        if top == node:
            return comp


def shortest_cycle(graph, component):
    """A shortest circle of the component that crosses a folder (breadth
    first from each of its files, inside the component)."""
    members = set(component)
    best = None
    for start in component:
        path = shortest_path_back(graph, members, start)
        crosses = path and len({folder_of(f) for f in path}) > 1
        if crosses and (best is None or len(path) < len(best)):
            best = path
    return best or [component[0]]


def shortest_path_back(graph, members, start):
    parent = {start: None}
    queue = [start]
    for node in queue:
        for nxt in sorted(graph.get(node, ())):
            if nxt == start:
                path = [node]
                while parent[path[-1]] is not None:
                    path.append(parent[path[-1]])
                return path[::-1]
            if nxt in members and nxt not in parent:
                parent[nxt] = node
                queue.append(nxt)
    return None


# ------------------------------------------------------------- output

def summary(root, files, includes):
    edges = folder_edges(includes)
    counts = c_files_per_folder(files)
    lines = defaultdict(int)
    for f in files:
        lines[folder_of(f)] += count_lines(read_text(root, f))
    print("| folder | .c files | lines | includes |")
    print("|---|---:|---:|---|")
    for folder in sorted(lines):
        used = ", ".join(b[len("src/"):] for b in sorted(edges.get(folder, {})))
        print("| %s | %d | %d | %s |" % (folder, counts[folder], lines[folder], used or "-"))


RULES = (
    "1, no folder of src/ holds more than %d .c files" % MAX_C_FILES,
    "2, %s is under %d lines" % (TRACE_C, MAX_TRACE_C_LINES + 1),
    "3, no function over %d lines (first line of the definition to the closing brace)"
    % MAX_FUNCTION_LINES,
    "4, no *_internal.h is included from another folder",
    "5, no include circle spans two folders",
)


def report(results, counted):
    broken = 0
    for title, lines in zip(RULES, results):
        print("rule %s: %s" % (title, "BROKEN" if lines else "ok"))
        for line in lines:
            print("  " + line)
        broken += bool(lines)
    print("layout: %d of %d rules broken (read: %s)" % (broken, len(RULES), counted))
    return broken


def main(argv):
    args = [a for a in argv if a != "--summary"]
    if len(args) > 1 or any(a.startswith("-") for a in args):
        sys.stderr.write("usage: check_layout.py [--summary] [SOURCE_DIR]\n")
        return 2
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    if not os.path.isdir(os.path.join(root, "src")):
        sys.stderr.write("check_layout: no src/ in %s\n" % root)
        return 2
    files = source_files(root)
    texts = {f: read_text(root, f) for f in files}
    includes = [inc for f in files for inc in find_includes(root, f, texts[f])]
    if "--summary" in argv:
        summary(root, files, includes)
        return 0
    try:
        functions = [fn for f in files for fn in find_functions(f, texts[f])]
    except ParseError as e:
        sys.stderr.write("check_layout: cannot parse %s\n" % e)
        return 2
    results = (rule_crowded_folders(files), rule_trace_c(root),
               rule_long_functions(functions), rule_internal_headers(includes),
               rule_include_circles(includes))
    counted = "%d files, %d functions, %d includes" % (len(files), len(functions),
                                                        len(includes))
    return 1 if report(results, counted) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
