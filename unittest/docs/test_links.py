# SPDX-License-Identifier: GPL-2.0-only (GRANSPH: LICENSE)
"""Every relative link resolves: in README.md, doc/, examples/*/README.md, bench/ and
validation/, each Markdown link or image ([text](target), ![alt](target), <img src=...>) and each
reStructuredText link (`text <target>`_, .. image::/.. figure::) that is not a URL names
a file or folder of the tree, and a #fragment into a Markdown file names one of its
headings (GitHub's anchors: lower case, punctuation dropped, spaces to hyphens)."""

import glob
import os
import re
import sys

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

MD_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
RST_LINK = re.compile(r"`[^`<]*<([^`>]+)>`__?")
RST_IMAGE = re.compile(r"^\s*\.\. (?:image|figure|include|literalinclude)::\s*(\S+)", re.M)
HTML_SRC = re.compile(r"<(?:img|a)\s[^>]*?(?:src|href)=\"([^\"]+)\"")
FENCE = re.compile(r"^(```|~~~).*?^\1", re.M | re.S)


def files():
    pats = ["README.md", "doc/*.rst", "doc/*.md", "examples/*/README.md", "bench/*.md",
            "validation/*.md", "validation/**/*.md"]
    seen = []
    for p in pats:
        for f in sorted(glob.glob(os.path.join(TOP, p), recursive=True)):
            if f not in seen:
                seen.append(f)
    return seen


def anchors(path):
    out = set()
    counts = {}
    with open(path) as f:
        text = FENCE.sub("", f.read())
    for line in text.splitlines():
        m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not m:
            continue
        slug = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
        n = counts.get(slug, 0)
        counts[slug] = n + 1
        out.add(slug if n == 0 else f"{slug}-{n}")
    for m in re.finditer(r"<a\s+(?:name|id)=\"([^\"]+)\"", text):
        out.add(m.group(1))
    return out


def targets(path):
    with open(path) as f:
        text = f.read()
    if path.endswith(".md"):
        text = FENCE.sub(lambda m: "\n" * m.group(0).count("\n"), text)
        found = [(m.start(), m.group(1)) for m in MD_LINK.finditer(text)]
        found += [(m.start(), m.group(1)) for m in HTML_SRC.finditer(text)]
    else:
        found = [(m.start(), m.group(1)) for m in RST_LINK.finditer(text)]
        found += [(m.start(1), m.group(1)) for m in RST_IMAGE.finditer(text)]
    for at, target in found:
        yield text.count("\n", 0, at) + 1, target


def main():
    bad = []
    checked = 0
    for path in files():
        for line, target in targets(path):
            if re.match(r"[a-z][a-z0-9+.-]*:", target) or target.startswith("//"):
                continue          # a URL, mailto:
            name, _, fragment = target.partition("#")
            where = path if not name else os.path.normpath(os.path.join(os.path.dirname(path), name))
            checked += 1
            rel = os.path.relpath(path, TOP)
            if not os.path.exists(where):
                bad.append(f"{rel}:{line}: {target}: no such file")
            elif fragment and where.endswith(".md") and fragment not in anchors(where):
                bad.append(f"{rel}:{line}: {target}: no heading #{fragment} in "
                           f"{os.path.relpath(where, TOP)}")
    for b in bad:
        print("FAIL:", b)
    print(f"{checked} relative links in {len(files())} files, {len(bad)} broken")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
