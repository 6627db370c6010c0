#!/usr/bin/env python3
"""check_links.py - every relative link and image in the documentation resolves.

Usage: python3 scripts/check_links.py [FILE.md ...]
(default: README.md and docs/*.md, from the repository root)

For each inline link [text](target) and image ![alt](target) outside code
(fenced blocks and `code spans`), a relative target must name an existing
file or directory, relative to the Markdown file that holds it; a #anchor
(alone, or after a .md target) must name a heading of that file, as GitHub
makes anchors of headings: lower case, punctuation other than '-' and '_'
dropped, each space a '-', a repeated heading given -1, -2, ...
Absolute URLs (scheme:) are not fetched. Prints each broken link as
FILE:LINE: and exits 1 if there is one, else prints a count and exits 0.
"""
import glob
import os
import re
import sys

LINK = re.compile(r'!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\)')
FENCE = re.compile(r'^\s*(```|~~~)')
CODE_SPAN = re.compile(r'(`+)(.+?)\1')


def prose_lines(path):
    """(line number, text) of the lines outside fenced code, code spans blanked"""
    fenced = False
    with open(path, encoding='utf-8') as f:
        for n, line in enumerate(f, 1):
            if FENCE.match(line):
                fenced = not fenced
                continue
            if not fenced:
                yield n, CODE_SPAN.sub(lambda m: ' ' * len(m.group(0)), line)


def slug(heading):
    """GitHub's anchor for a heading's text"""
    text = re.sub(r'!?\[([^\]]*)\]\([^)]*\)', r'\1', heading)   # a link's text stays
    text = text.replace('`', '').strip().lower()
    text = re.sub(r'[^\w\- ]', '', text)
    return text.replace(' ', '-')


_anchor_cache = {}


def anchors(path):
    if path not in _anchor_cache:
        seen = {}
        found = set()
        for _, line in prose_lines(path):
            m = re.match(r'^ {0,3}(#{1,6})\s+(.*?)\s*#*\s*$', line)
            if not m:
                continue
            base = slug(m.group(2))
            k = seen.get(base, 0)
            seen[base] = k + 1
            found.add(base if k == 0 else '%s-%d' % (base, k))
        _anchor_cache[path] = found
    return _anchor_cache[path]


def check(path):
    """the broken links of one file, as messages"""
    bad = []
    here = os.path.dirname(path)
    for n, line in prose_lines(path):
        for m in LINK.finditer(line):
            target = m.group(1)
            if re.match(r'^[a-zA-Z][a-zA-Z0-9+.-]*:', target):
                continue   # http:, https:, mailto: ...
            file_part, _, anchor = target.partition('#')
            dest = os.path.normpath(os.path.join(here, file_part)) if file_part else path
            if not os.path.exists(dest):
                bad.append('%s:%d: %s: no such file (%s)' % (path, n, target, dest))
            elif anchor:
                if not dest.endswith('.md') or os.path.isdir(dest):
                    bad.append('%s:%d: %s: an anchor into a file that is not Markdown' % (path, n, target))
                elif anchor not in anchors(dest):
                    bad.append('%s:%d: %s: no heading makes the anchor #%s in %s' % (path, n, target, anchor, dest))
    return bad


def main(argv):
    files = argv[1:] or ['README.md'] + sorted(glob.glob('docs/*.md'))
    bad = []
    count = 0
    for path in files:
        if not os.path.isfile(path):
            bad.append('%s: no such file' % path)
            continue
        for _, line in prose_lines(path):
            count += len(LINK.findall(line))
        bad += check(path)
    for b in bad:
        print(b)
    if bad:
        print('check_links: %d broken of %d links in %d files' % (len(bad), count, len(files)))
        return 1
    print('check_links: %d links in %d files, all resolve' % (count, len(files)))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
