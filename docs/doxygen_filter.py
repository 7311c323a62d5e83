#!/usr/bin/env python3
"""Doxygen input filter: reads the project's plain `//` comments as documentation.

The public headers (include/puncture/) are documented with ordinary `//` comments, which Doxygen
ignores.  This filter rewrites them on the fly, so that the headers stay as they are:

  - each header is a Doxygen group named after it (puncture/problem.hpp: puncture_problem_hpp),
    documented by the comment block after `#pragma once`, holding what its namespace declares;
  - a comment block directly above a declaration documents it (`///`);
  - a comment after a declaration documents it (`///<`), with its continuation lines (comment-only
    lines starting in the same column);
  - a comment block followed by a blank line (a section heading) or by the end of its scope,
    and comments inside function bodies, stay plain comments; `// ----` rulers are dropped.

Doxygen's special characters in the comments' text are escaped, so that "c <= 0" or "#13" stay
text.  Usage (Doxyfile): INPUT_FILTER = "/usr/bin/python3 docs/doxygen_filter.py".
Standard library only.
"""
import re
import sys

RULER = re.compile(r"^\s*//\s*-{3,}\s*$")
COMMENT_ONLY = re.compile(r"^(\s*)//(.*)$")
NAMESPACE = re.compile(r"^\s*namespace\s+[\w:]+\s*\{")
TYPE_SCOPE = re.compile(r"^\s*(namespace|struct|class|union|enum)\b")
SPECIAL = re.compile(r"([\\@<>#&$%])")


def escape(text):
    """Doxygen reads these characters as commands or markup; in this project they are text."""
    return SPECIAL.sub(r"\\\1", text)


def split_code_comment(line):
    """(code, comment) with the comment's text after `//`, or (line, None); skips string
    literals and `/* */` on the line."""
    i, quote = 0, None
    while i < len(line):
        c = line[i]
        if quote:
            if c == "\\":
                i += 1
            elif c == quote:
                quote = None
        elif c in "\"'":
            quote = c
        elif line.startswith("/*", i):
            end = line.find("*/", i + 2)
            if end < 0:
                return line, None
            i = end + 1
        elif line.startswith("//", i):
            return line[:i], line[i + 2:]
        i += 1
    return line, None


def braces(code):
    return code.count("{") - code.count("}")


def header_name(path):
    """The header as it is included: puncture/materials/gent.hpp."""
    parts = path.replace("\\", "/").split("/include/")
    return parts[-1]


def group_id(path):
    """The header's Doxygen group: puncture_materials_gent_hpp."""
    return re.sub(r"[^A-Za-z0-9]", "_", header_name(path))


def filter_header(path, lines):
    out = []
    scopes = []  # True: a type or namespace scope (documented), False: a body (left alone)
    trailing_column = None  # column of the last trailing comment, for its continuation lines
    i = 0
    while i < len(lines):
        line = lines[i]
        in_body = not all(scopes)
        comment_only = COMMENT_ONLY.match(line)
        if line.strip() == "#pragma once":
            # The header is a group of its own (its declarations, without the namespace that
            # every header shares), documented by the comment that opens it.
            out += [line, f"/// \\defgroup {group_id(path)} {header_name(path)}"]
            i += 1
            while i < len(lines) and COMMENT_ONLY.match(lines[i]):
                out.append("///" + escape(COMMENT_ONLY.match(lines[i]).group(2)))
                i += 1
            continue
        if in_body:
            code, _ = split_code_comment(line)
            update_scopes(scopes, code)
            out.append(line)
            i += 1
            continue
        if RULER.match(line):
            out.append("")
            trailing_column = None
            i += 1
            continue
        if comment_only:
            indent, text = comment_only.groups()
            if trailing_column is not None and len(indent) == trailing_column:
                out.append(indent + "///<" + escape(text))
                i += 1
                continue
            # A block: documents what follows it directly, else it is a section heading.
            j = i
            while j < len(lines) and COMMENT_ONLY.match(lines[j]) and not RULER.match(lines[j]):
                j += 1
            follows = lines[j] if j < len(lines) else ""
            documents = follows.strip() != "" and not follows.lstrip().startswith(("#", "}"))
            for k in range(i, j):
                indent, text = COMMENT_ONLY.match(lines[k]).groups()
                out.append(indent + ("///" + escape(text) if documents else "//" + text))
            trailing_column = None
            i = j
            continue
        code, comment = split_code_comment(line)
        if not scopes and NAMESPACE.match(code) and braces(code) > 0:
            # Doxygen groups a namespace's members only from inside it.
            update_scopes(scopes, code)
            out += [line, f"/// \\addtogroup {group_id(path)}", "/// @{"]
            i += 1
            continue
        if len(scopes) == 1 and braces(code) < 0:
            out.append("/// @}")
        if comment is not None and code.strip() and not code.strip().startswith("}"):
            trailing_column = len(code)
            out.append(code + "///<" + escape(comment))
        else:
            trailing_column = None
            out.append(line)
        update_scopes(scopes, code)
        i += 1
    return out


def update_scopes(scopes, code):
    net = braces(code)
    if net > 0:
        documented = bool(TYPE_SCOPE.match(code)) and all(scopes)
        scopes.extend([documented] * net)
    elif net < 0:
        del scopes[net:]


def main():
    with open(sys.argv[1], encoding="utf-8") as f:
        lines = f.read().split("\n")
    sys.stdout.write("\n".join(filter_header(sys.argv[1], lines)) + "\n")


if __name__ == "__main__":
    main()
