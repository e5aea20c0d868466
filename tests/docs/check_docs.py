#!/usr/bin/env python3
"""Checks what the documentation says about the tree, where a machine can check it.

    python3 tests/docs/check_docs.py [SOURCE_DIR]     (ctest: docs_consistency)

1. docs/architecture.md: every path it names under a module folder (`calc/direct_reach`,
   `geometry/cgal/room.cpp`, `tests/cli`; a name without an extension may be a .h or a .cpp),
   every file name it gives alone (`polygon.h`), every CMake target (`luxgrid_calc`) and option
   (`LUXGRID_WERROR`), and every identifier it quotes as code (`make_plan`,
   `geometry::Visibility`, `table_view()`) exists in the tree.
2. README.md and docs/*.md: every relative link resolves to a file, and its `#anchor` to a heading
   of that page by GitHub's rule (lower case, punctuation dropped, spaces to hyphens, -1, -2 ...
   for repeats).
3. A section cited by its title in the docs or in a source comment (`docs/nearfield.md, "The
   table rung"`) exists in that page: the title begins one of its headings or of its bold or
   italic lead-ins.

Prints each failure with its file and line and exits 1 if there is one.
"""
import functools
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(os.path.dirname(__file__), "..", ".."))
MODULE_FOLDERS = ("app", "bench", "calc", "cases", "cli", "docs", "examples", "fuzz", "geometry",
                  "photometry", "project", "python", "report", "scripts", "study", "tests", "util")
SOURCE_EXTENSIONS = (".h", ".cpp", ".py", ".sh", ".txt", ".cmake")

# Section citations that another branch of issue 35 rewrites (the four-lane kernels' files);
# each entry is (file, cited page, cited title), so nothing else is let through, and an entry
# whose citation is gone fails too, so the list empties as the files are rewritten.
PENDING_CITATIONS = set()

failures = []


def fail(path, line, message):
    rel = os.path.relpath(path, ROOT) if os.path.isabs(path) else path
    failures.append(f"{rel}:{line}: {message}")


def tree_files():
    """Every file of the tree but builds, version control and hidden folders."""
    for folder, dirs, files in os.walk(ROOT):
        dirs[:] = [d for d in dirs if not d.startswith((".", "build"))]
        for f in files:
            yield os.path.relpath(os.path.join(folder, f), ROOT)


FILES = set(tree_files())
BASENAMES = {os.path.basename(f) for f in FILES}
SOURCES = [f for f in FILES if f.endswith(SOURCE_EXTENSIONS) and not f.startswith("tests/data/")]


@functools.lru_cache(maxsize=None)
def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8", errors="replace") as f:
        return f.read()


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def exists(rel):
    rel = rel.rstrip("/")
    return (rel in FILES or os.path.isdir(os.path.join(ROOT, rel)) or
            any(rel + ext in FILES for ext in (".h", ".cpp")))


# --- 1. the names architecture.md gives ------------------------------------------------------

def code_words():
    words = set()
    for f in SOURCES:
        words.update(re.findall(r"\w+", read(f)))
    return words


def cmake_targets():
    targets, options = set(), set()
    for f in FILES:
        if os.path.basename(f) != "CMakeLists.txt":
            continue
        text = read(f)
        for name in re.findall(
                r"(?:add_library|add_executable|luxgrid_module|sanitized_library|pybind11_add_module)\(\s*(\w+)", text):
            targets.add(name)
        for name in re.findall(r"luxgrid_tests\((\w+)", text):
            targets.add(name + "_tests")
        for names in re.findall(r"foreach\(\w+ ([\w ]+)\)", text):
            targets.update(names.split())
        options.update(re.findall(r"option\((\w+)", text))
    return targets, options


def check_architecture():
    rel = "docs/architecture.md"
    text = read(rel)
    path = os.path.join(ROOT, rel)
    folders = "|".join(MODULE_FOLDERS)
    for m in re.finditer(r"(?<![\w/.-])((?:%s)/[\w./-]*\w)" % folders, text):
        if not exists(m.group(1)):
            fail(path, line_of(text, m.start()), f"names '{m.group(1)}', which is not in the tree")
    for m in re.finditer(r"(?<![\w/.*-])([\w-]+\.(?:h|cpp|py|sh))\b", text):
        if m.group(1) not in BASENAMES:
            fail(path, line_of(text, m.start()),
                 f"names the file '{m.group(1)}', which no folder has")
    targets, options = cmake_targets()
    for m in re.finditer(r"\b(luxgrid_\w+|\w+_tests)\b", text):
        if m.group(1) not in targets:
            fail(path, line_of(text, m.start()), f"names the target '{m.group(1)}', which no "
                 "CMakeLists.txt defines")
    words = code_words()
    for m in re.finditer(r"\b(LUXGRID_[A-Z_]+)\b", text):
        if m.group(1) not in options and m.group(1) not in words:
            fail(path, line_of(text, m.start()), f"names '{m.group(1)}', which is neither a "
                 "CMake option nor a name in the sources")
    for m in re.finditer(r"`([A-Za-z_][\w:]*)(\(\))?`", text):
        name = m.group(1)
        looks_like_code = ("_" in name or "::" in name or m.group(2) or
                           re.search(r"[a-z][A-Z]", name))
        if not looks_like_code:
            continue
        for part in filter(None, name.split("::")):
            if part not in words and part not in targets:
                fail(path, line_of(text, m.start()),
                     f"quotes '{name}', but no source file has '{part}'")


# --- 2. links and anchors ----------------------------------------------------------------------

def heading_slug(title):
    """GitHub's anchor of a heading: link text kept, markup and punctuation dropped."""
    title = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", title)
    slug = re.sub(r"[^\w\- ]", "", title.strip().lower())
    return slug.replace(" ", "-")


@functools.lru_cache(maxsize=None)
def headings(rel):
    """The headings of a Markdown page (outside code fences) as written."""
    titles, fenced = [], False
    for line in read(rel).splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced:
            m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
            if m:
                titles.append(m.group(1))
    return titles


@functools.lru_cache(maxsize=None)
def anchors(rel):
    seen, result = {}, set()
    for title in headings(rel):
        slug = heading_slug(title)
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        result.add(slug if n == 0 else f"{slug}-{n}")
    return result


def markdown_pages():
    return sorted(f for f in FILES if f == "README.md" or
                  (f.startswith("docs/") and f.endswith(".md")))


def check_links():
    for rel in markdown_pages():
        text = read(rel)
        text_without_code = re.sub(r"```.*?```", lambda m: "\n" * m.group(0).count("\n"), text,
                                   flags=re.S)
        for m in re.finditer(r"\]\(([^)\s]+)\)", text_without_code):
            target = m.group(1)
            if re.match(r"[a-z]+:", target):  # http:, https:, mailto:
                continue
            file_part, _, anchor = target.partition("#")
            where = os.path.normpath(os.path.join(os.path.dirname(rel), file_part)) \
                if file_part else rel
            if where not in FILES and not os.path.isdir(os.path.join(ROOT, where)):
                fail(rel, line_of(text, m.start()), f"links to '{target}': no file '{where}'")
            elif anchor and where.endswith(".md") and anchor not in anchors(where):
                fail(rel, line_of(text, m.start()),
                     f"links to '{target}': '{where}' has no heading with the anchor '#{anchor}'")


# --- 3. sections cited by title ----------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def section_titles(rel):
    """What a citation may name: a heading, or a paragraph's or item's bold or italic lead-in."""
    text = read(rel)
    titles = [re.sub(r"[`*]", "", t) for t in headings(rel)]
    titles += [re.sub(r"`", "", t) for t in re.findall(r"\*\*([^*]+)\*\*", text)]
    titles += [re.sub(r"`", "", t) for t in re.findall(r"(?<![*\w])\*([^*\n]+)\*(?![*\w])", text)]
    return titles


def comment_text(rel):
    """A file's text with comment markers dropped and lines joined, so a citation that wraps
    is read whole; offsets map back to lines through the kept newlines' count."""
    text = read(rel)
    if rel.endswith(".md"):
        return text
    return re.sub(r"\n[ \t]*(?://+|#+)?[ \t]*", "\n", text)


def check_citations():
    pages = {os.path.basename(p): p for p in markdown_pages()}
    pending_seen = set()
    for rel in sorted(set(markdown_pages()) | set(SOURCES)):
        text = comment_text(rel)
        # A page, then one title in quotes or several ("A" and "B", "A", "B").
        pattern = r"\b([\w-]+\.md),?\s+\(?(\"[^\"]+\"(?:\s*(?:,|and|or)\s+\"[^\"]+\")*)"
        for m in re.finditer(pattern, text):
            page = m.group(1)
            for quoted in re.findall(r"\"([^\"]+)\"", m.group(2)):
                title = " ".join(quoted.replace("`", "").split())
                if (rel, page, title) in PENDING_CITATIONS:
                    pending_seen.add((rel, page, title))
                    continue
                if page not in pages:
                    continue
                if not any(t.startswith(title) for t in section_titles(pages[page])):
                    fail(rel, line_of(text, m.start()),
                         f"cites {page}, \"{title}\": no heading or lead-in of it begins so")

    for rel, page, title in sorted(PENDING_CITATIONS - pending_seen):
        fail(rel, 0, f"no longer cites {page}, \"{title}\": take it out of PENDING_CITATIONS")


check_architecture()
check_links()
check_citations()
for f in failures:
    print(f)
print(f"check_docs: {len(failures)} problem(s)" if failures else "check_docs: all names resolve")
sys.exit(1 if failures else 0)
