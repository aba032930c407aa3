#!/usr/bin/env python3
# Checks that README.md and docs/*.md cannot drift from the code (issue 27). Three checks, one per
# ctest test (tests/docs/CMakeLists.txt):
#   snippets ROOT        every ```holon block is a bundled rule file (rules/library, examples), or a
#                        run of its consecutive lines, comments and blank lines aside; a block that
#                        declares a system must be fenced as holon, so none escapes the check
#   links ROOT           every relative link reaches a file, every #anchor a heading of its page
#                        (GitHub's slugs), and docs/README.md lists every page under docs/
#   options ROOT HOLON   every --option written after `holon SUBCOMMAND` is one the subcommand's
#                        --help lists (the subcommands from `holon --help`), so a renamed or
#                        removed option cannot stay documented
# Pages are found by glob: a new page under docs/ is checked without being registered.
import glob
import os
import re
import subprocess
import sys


def pages(root):
    return [os.path.join(root, 'README.md')] + sorted(glob.glob(os.path.join(root, 'docs', '*.md')))


def fenced_blocks(text):
    """(line number of the opening fence, info string, lines) of each fenced code block."""
    blocks, current = [], None
    for number, line in enumerate(text.split('\n'), 1):
        if line.startswith('```'):
            if current is None:
                current = (number, line[3:].strip(), [])
            else:
                blocks.append(current)
                current = None
        elif current is not None:
            current[2].append(line)
    return blocks


def prose_lines(text):
    """(line number, line) outside fenced code blocks."""
    inside = False
    for number, line in enumerate(text.split('\n'), 1):
        if line.startswith('```'):
            inside = not inside
        elif not inside:
            yield number, line


def rel(root, path):
    return os.path.relpath(path, root)


def holon_lines(lines):
    """A rule text as compared: comments, trailing blanks and empty lines dropped."""
    out = []
    for line in lines:
        line = line.split('//', 1)[0].rstrip()
        if line:
            out.append(line)
    return out


def check_snippets(root):
    sources = {}
    for pattern in ('rules/library/**/*.holon', 'examples/**/*.holon'):
        for path in glob.glob(os.path.join(root, pattern), recursive=True):
            with open(path, encoding='utf-8') as f:
                sources[rel(root, path)] = holon_lines(f.read().split('\n'))
    errors, checked = [], 0
    for page in pages(root):
        with open(page, encoding='utf-8') as f:
            blocks = fenced_blocks(f.read())
        for number, info, lines in blocks:
            where = f'{rel(root, page)}:{number}'
            body = holon_lines(lines)
            if info != 'holon':
                if body and re.match(r'system\s+\w+\s*$', body[0]):
                    errors.append(f'{where}: a rule system fenced as ```{info}; fence it as ```holon so that it is checked')
                continue
            checked += 1
            if not body:
                errors.append(f'{where}: an empty holon block')
                continue
            found = [name for name, src in sources.items()
                     if any(src[i:i + len(body)] == body for i in range(len(src) - len(body) + 1))]
            if not found:
                # Name the first line that no file continues, against the file that matches longest.
                best, best_len = None, -1
                for name, src in sources.items():
                    for i in range(len(src)):
                        k = 0
                        while k < len(body) and i + k < len(src) and src[i + k] == body[k]:
                            k += 1
                        if k > best_len:
                            best, best_len = name, k
                errors.append(f'{where}: this holon block is in no file of rules/library or examples; '
                              f'it follows {best} for {best_len} line(s), then has {body[best_len]!r}. '
                              f'Copy the file\'s lines, or change the file and the block together')
    for e in errors:
        print(e)
    print(f'{checked} holon blocks checked against {len(sources)} rule files')
    return not errors and checked > 0


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = heading.strip().lower().replace('`', '')
    text = re.sub(r'\[([^\]]*)\]\([^)]*\)', r'\1', text)
    text = ''.join(c for c in text if c.isalnum() or c in ' -_')
    return text.replace(' ', '-')


def anchors(path):
    seen, out = {}, set()
    with open(path, encoding='utf-8') as f:
        for _, line in prose_lines(f.read()):
            m = re.match(r'#{1,6}\s+(.*)', line)
            if m:
                s = slug(m.group(1))
                n = seen.get(s, 0)
                seen[s] = n + 1
                out.add(s if n == 0 else f'{s}-{n}')
    return out


def check_links(root):
    errors, count = [], 0
    for page in pages(root):
        with open(page, encoding='utf-8') as f:
            text = f.read()
        for number, line in prose_lines(text):
            line = re.sub(r'`[^`]*`(?!\])', '', line)  # code spans, unless they are a link's text
            for target in re.findall(r'\]\(([^)\s]+)\)', line):
                if re.match(r'[a-z]+:', target):
                    continue
                count += 1
                where = f'{rel(root, page)}:{number}'
                path, _, anchor = target.partition('#')
                dest = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
                if not os.path.exists(dest):
                    errors.append(f'{where}: link to {target}: {rel(root, dest)} does not exist')
                elif anchor and dest.endswith('.md') and anchor not in anchors(dest):
                    errors.append(f'{where}: link to {target}: {rel(root, dest)} has no heading with anchor #{anchor}')
    index = os.path.join(root, 'docs', 'README.md')
    with open(index, encoding='utf-8') as f:
        listed = set(re.findall(r'\]\(([^)#\s]+\.md)', f.read()))
    for page in pages(root)[1:]:
        name = os.path.basename(page)
        if name != 'README.md' and name not in listed:
            errors.append(f'docs/README.md: the index does not list docs/{name}; add a row for it')
    for e in errors:
        print(e)
    print(f'{count} links checked in {len(pages(root))} pages')
    return not errors and count > 0


def subcommands(holon):
    """The subcommands `holon --help` lists, so that a new one is checked without being named here."""
    r = subprocess.run([holon, '--help'], capture_output=True, text=True)
    listed = r.stdout.split('Subcommands:', 1)[-1]
    return tuple(re.findall(r'^  ([a-z]+)\s', listed, re.M))


def commands(text, subs):
    """(line number, subcommand, options) of each `holon SUBCOMMAND ...` written in code."""
    spans = []
    for number, info, lines in fenced_blocks(text):
        joined, start = '', None
        for k, line in enumerate(lines):
            line = re.sub(r'\s#\s.*$', '', line)  # a shell comment
            if start is None:
                start = number + 1 + k
            joined += ' ' + line.rstrip('\\')
            if not line.endswith('\\'):
                spans.append((start, joined))
                joined, start = '', None
    paragraph, start = [], None  # a code span may wrap onto the next line of its paragraph
    for number, line in list(prose_lines(text)) + [(0, '')]:
        if line.strip():
            start = start or number
            paragraph.append(line)
            continue
        spans += [(start, s) for s in re.findall(r'`([^`]+)`', ' '.join(paragraph))]
        paragraph, start = [], None
    out = []
    for number, span in spans:
        for m in re.finditer(r'(?:^|[\s/])holon\s+(%s)\b(.*?)(?=$|[;|]|&&)' % '|'.join(subs), span):
            out.append((number, m.group(1), re.findall(r'(?<![\w-])--[a-z][a-z0-9-]*', m.group(2))))
    return out


def check_options(root, holon):
    helps, errors, count = {}, [], 0
    subs = subcommands(holon)
    if not subs:
        errors.append(f'{holon} --help lists no subcommands')
    for sub in subs:
        r = subprocess.run([holon, sub, '--help'], capture_output=True, text=True)
        if r.returncode != 0:
            errors.append(f'holon {sub} --help: exit {r.returncode}')
        helps[sub] = set(re.findall(r'--[a-z][a-z0-9-]*', r.stdout))
    for page in pages(root):
        with open(page, encoding='utf-8') as f:
            text = f.read()
        for number, sub, options in commands(text, subs):
            for option in options:
                count += 1
                if option not in helps[sub]:
                    errors.append(f'{rel(root, page)}:{number}: holon {sub} has no option {option} (holon {sub} --help)')
    for e in errors:
        print(e)
    print(f'{count} options of documented holon commands checked')
    return not errors and count > 0


if __name__ == '__main__':
    what, root = sys.argv[1], sys.argv[2]
    ok = {'snippets': lambda: check_snippets(root),
          'links': lambda: check_links(root),
          'options': lambda: check_options(root, sys.argv[3])}[what]()
    sys.exit(0 if ok else 1)
