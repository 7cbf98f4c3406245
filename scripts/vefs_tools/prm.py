"""deal.II parameter files (.prm): read the entries of a run's
parameters.prm, and change entries of a scene's text the way the
benchmarks derive their runs from one scene (standard library only).

read_parameters(path_or_dir)
    Reads the ``parameters.prm`` a vefs run writes into its output directory
    (deal.II ParameterHandler PRM format; any input prm file works too).
    Returns a dict 'Subsection/Entry' -> value string ('Entry' at the top
    level, 'A/B/Entry' for nested subsections).  parameter(), parameter_float()
    and parameter_floats() get one entry with a readable error message.

set_entry(text, path, name, value), apply_settings(text, settings)
    The text of a prm file with entries set; comments and layout are kept.
"""

import os
import re


def parameters_path(path_or_dir):
    """Path of parameters.prm given the file itself or its directory."""
    if os.path.isdir(path_or_dir):
        return os.path.join(path_or_dir, "parameters.prm")
    return path_or_dir


def split_comment(line):
    """(code, comment) of a PRM line: the code before its '#' comment (a
    backslash-escaped '\\#' is kept as written) and the comment."""
    out = []
    i = 0
    while i < len(line):
        c = line[i]
        if c == "\\" and i + 1 < len(line) and line[i + 1] == "#":
            out.append("\\#")
            i += 2
            continue
        if c == "#":
            return "".join(out), line[i:]
        out.append(c)
        i += 1
    return "".join(out), ""


def logical_lines(lines):
    """Group physical lines (without line ends) into logical lines joined by a
    trailing backslash.  Yields (first index, last index, code, comment)."""
    i = 0
    n = len(lines)
    while i < n:
        first = i
        code, comment = split_comment(lines[i])
        while code.rstrip().endswith("\\") and i + 1 < n:
            i += 1
            c2, comment2 = split_comment(lines[i])
            code = code.rstrip()[:-1] + " " + c2.strip()
            comment = comment2 or comment
        yield first, i, code, comment
        i += 1


def read_parameters(path_or_dir):
    """Read a deal.II ParameterHandler file in PRM format into a dict
    'Subsection/Entry' -> value (a string, surrounding blanks removed).

    Understands what ParameterHandler::print_parameters(..., PRM) writes and
    what it reads: '#' comments ('\\#' is a literal '#'), lines continued
    by a trailing backslash, 'subsection NAME' ... 'end' (nested), and
    'set NAME = VALUE' (split at the first '=').  Runs of blanks in
    subsection and entry names are reduced to one; names are kept as
    written otherwise (case-sensitive, like deal.II).  A later 'set' of the
    same entry wins.  'include' lines are not followed.  Raises ValueError
    with the line number on anything else (unbalanced 'end', a line that
    is none of the above, an unclosed subsection)."""
    path = parameters_path(path_or_dir)
    with open(path) as f:
        physical = f.read().splitlines()

    result = {}
    stack = []
    for first, _, code, _ in logical_lines(physical):
        number = first + 1
        line = code.replace("\\#", "#")
        text = line.strip()
        if not text:
            continue
        words = text.split(None, 1)
        keyword = words[0].lower()
        if keyword == "subsection":
            if len(words) < 2:
                raise ValueError("%s:%d: 'subsection' without a name"
                                 % (path, number))
            stack.append(" ".join(words[1].split()))
        elif keyword == "end" and len(words) == 1:
            if not stack:
                raise ValueError("%s:%d: 'end' without a subsection"
                                 % (path, number))
            stack.pop()
        elif keyword == "set":
            rest = words[1] if len(words) > 1 else ""
            if "=" not in rest:
                raise ValueError("%s:%d: 'set' without '=': %s"
                                 % (path, number, text))
            name, value = rest.split("=", 1)
            name = " ".join(name.split())
            if not name:
                raise ValueError("%s:%d: 'set' without a name"
                                 % (path, number))
            result["/".join(stack + [name])] = value.strip()
        elif keyword == "include":
            continue
        else:
            raise ValueError("%s:%d: not a PRM line: %s" % (path, number,
                                                            text))
    if stack:
        raise ValueError("%s: subsection '%s' not closed by 'end'"
                         % (path, "/".join(stack)))
    return result


def parameter(prm, key, source="parameters.prm"):
    """prm[key] with a readable error message if the entry is missing."""
    try:
        return prm[key]
    except KeyError:
        raise KeyError("entry '%s' not found in %s" % (key, source))


def parameter_float(prm, key, source="parameters.prm"):
    """The entry key as a float (ValueError if it is not a number)."""
    value = parameter(prm, key, source)
    try:
        return float(value)
    except ValueError:
        raise ValueError("entry '%s' in %s is not a number: '%s'"
                         % (key, source, value))


def parameter_floats(prm, key, source="parameters.prm"):
    """The entry key as a list of floats: a comma separated list (as
    Gravity, the cavity corners or the probe point), or [] if empty."""
    value = parameter(prm, key, source)
    if not value.strip():
        return []
    try:
        return [float(x) for x in value.split(",")]
    except ValueError:
        raise ValueError("entry '%s' in %s is not a comma separated list of "
                         "numbers: '%s'" % (key, source, value))


# --------------------------------------------------------------------------
# editing
# --------------------------------------------------------------------------

_SUBSECTION = re.compile(r"^\s*subsection\s+(.*?)\s*$", re.IGNORECASE)
_END = re.compile(r"^\s*end\s*$", re.IGNORECASE)
_SET = re.compile(r"^(\s*set\s+)(.*?)(\s*=\s*)(.*?)(\s*)$",
                  re.IGNORECASE | re.DOTALL)


def _norm(name):
    return " ".join(name.split())


def set_entry(text, path, name, value):
    """Return the prm text with entry `name` in subsection `path` (a list of
    subsection names, [] for the top level) set to `value`.

    All existing 'set name = ...' lines in that subsection are changed
    (indentation and trailing comments are kept).  If there is none, the
    line is added at the end of the (last) matching subsection block,
    creating missing subsections as needed.
    """
    path = [_norm(p) for p in path]
    name_n = _norm(name)
    lines = text.split("\n")
    stack = []
    blocks = {(): (0, len(lines))}  # path -> (start, index of 'end' line)
    open_starts = []
    replacements = []  # (first, last, new line)
    for first, last, code, comment in logical_lines(lines):
        m = _SUBSECTION.match(code)
        if m and code.strip():
            stack.append(_norm(m.group(1)))
            open_starts.append(first)
            continue
        if _END.match(code):
            if stack:
                blocks[tuple(stack)] = (open_starts[-1], first)
                stack.pop()
                open_starts.pop()
            continue
        m = _SET.match(code)
        if m and stack == path and _norm(m.group(2)) == name_n:
            indent = m.group(1)
            sep = m.group(3)
            new = "%s%s%s%s" % (indent, m.group(2).strip(), sep, value)
            if comment:
                new += (m.group(5) or "  ") + comment
            replacements.append((first, last, new))

    if replacements:
        for first, last, new in reversed(replacements):
            lines[first:last + 1] = [new]
        return "\n".join(lines)

    # not found: insert into the deepest existing prefix of `path`
    depth = len(path)
    while depth > 0 and tuple(path[:depth]) not in blocks:
        depth -= 1
    new_lines = []
    for k in range(depth, len(path)):
        new_lines.append("  " * k + "subsection " + path[k])
    new_lines.append("  " * len(path) + "set %s = %s" % (name_n, value))
    for k in reversed(range(depth, len(path))):
        new_lines.append("  " * k + "end")
    if depth == 0:
        # top level: append at the end of the file
        while lines and lines[-1].strip() == "":
            lines.pop()
        lines += [""] + new_lines + [""]
    else:
        end_index = blocks[tuple(path[:depth])][1]
        lines[end_index:end_index] = new_lines
    return "\n".join(lines)


def parse_setting(item):
    """'Section/Sub/Entry=value' -> (['Section', 'Sub'], 'Entry', 'value'):
    the form in which the benchmarks take prm changes on the command line;
    ValueError without '=' or with an empty name."""
    if "=" not in item:
        raise ValueError("%r: expected SECTION/ENTRY=VALUE" % item)
    key, value = item.split("=", 1)
    parts = [x.strip() for x in key.split("/")]
    if any(not x for x in parts):
        raise ValueError("%r: empty section or entry name" % item)
    return parts[:-1], parts[-1], value.strip()


def apply_settings(text, settings):
    """The prm text with each 'Section/Sub/Entry=value' of `settings` set."""
    for item in settings or []:
        path, name, value = parse_setting(item)
        text = set_entry(text, path, name, value)
    return text
