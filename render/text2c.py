#!/usr/bin/env python3
"""Turn the part of a markdown file after a marker line into a C array of
lines, for a help text printed by the tool.

usage: text2c.py INPUT.md OUTPUT.h NAME

From the line after the one that starts with "<!-- curvefig help" to the
end: fence lines (```) are left out, a heading ("## Title", "### Title")
becomes "TITLE" without the blank line that follows it, and every other
line is kept as it is.  OUTPUT.h defines
static const char *const NAME[] = { "line\\n", ..., NULL };
"""
import sys


def main():
    src, out, name = sys.argv[1], sys.argv[2], sys.argv[3]
    with open(src, encoding='utf-8') as f:
        lines = f.read().split('\n')
    start = [i for i, l in enumerate(lines) if l.startswith('<!-- curvefig help')]
    if len(start) != 1:
        sys.exit('%s: expected one "<!-- curvefig help" marker line' % src)
    text = []
    heading = False
    for line in lines[start[0] + 1:]:
        if line.startswith('```') or (heading and line == ''):
            continue
        heading = line.startswith('#')
        if heading:
            line = line.lstrip('#').strip().upper()
        text.append(line)
    while text and text[-1] == '':
        text.pop()
    with open(out, 'w', encoding='utf-8') as f:
        f.write('/* Generated from %s by render/text2c.py: do not edit. */\n'
                % src.split('/')[-1])
        f.write('static const char *const %s[] = {\n' % name)
        for line in text:
            esc = line.replace('\\', '\\\\').replace('"', '\\"')
            f.write('    "%s\\n",\n' % esc)
        f.write('    NULL,\n};\n')


if __name__ == '__main__':
    main()
