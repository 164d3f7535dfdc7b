#!/usr/bin/env python3
"""Prints the longest function bodies in C++ sources, longest first.

usage: scripts/function-lengths.py [--top N] [--over LINES] [PATH ...]
(default: src/ tools/ scenes/, top 10). A function is counted from the line
of its name to its closing brace, lambdas inside it included. The scan reads
braces, not C++: comments, strings, character literals and preprocessor
lines are skipped, and a
block counts as a function when the text before its '{' ends in a
parameter list (optionally followed by const, noexcept, override, an
initializer list or a trailing return type) and is not a control statement.
--over LINES exits 1 when any function is longer (a check for scripts).
"""
import argparse
import os
import re
import sys

SOURCE_SUFFIXES = ('.cpp', '.cc', '.h', '.hpp', '.inl')
CONTROL = re.compile(r'\b(if|for|while|switch|catch|do|else)\s*(\(|$)')
NOT_FUNCTIONS = re.compile(
    r'(^|\W)(namespace|class|struct|union|enum|extern\s+"C")(\W|$)')


def strip_comments_and_literals(text):
    """The text with comments, strings and char literals blanked (newlines
    kept, so line numbers stay)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i))
            i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if m:
                end = text.find(')' + m.group(1) + '"', i)
                end = n if end < 0 else end + len(m.group(1)) + 2
                out.append(re.sub(r'[^\n]', ' ', text[i:end]))
                i = end
            else:
                out.append(c)
                i += 1
        elif c in '"\'':
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            out.append(c + ' ' * (min(j, n) - i - 1) + (c if j < n else ''))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return ''.join(out)


def functions(path):
    """(name, first line, length in lines) of each function in `path`."""
    with open(path, encoding='utf-8', errors='replace') as f:
        text = strip_comments_and_literals(f.read())
    # Preprocessor lines (macros with parentheses) are no function heads.
    text = re.sub(r'(?m)^[ \t]*#.*$', lambda m: ' ' * len(m.group(0)), text)
    found = []
    stack = []  # per open brace: (is function, name, start line)
    head_start = 0  # where the text before the next '{' begins
    depth_in_function = 0
    for i, c in enumerate(text):
        if c == '{':
            head = text[head_start:i]
            is_function = False
            name = ''
            if depth_in_function == 0:
                flat = ' '.join(head.split())
                m = re.search(
                    r'([~\w:<>]+(?:operator\s*\S+?)?)\s*\(([^()]|\([^()]*\))*\)'
                    r'[\w\s&*:<>,\[\]()-]*$', flat)
                if (m and not CONTROL.search(flat.split('(')[0] + '(')
                        and not NOT_FUNCTIONS.search(flat.split('(')[0])
                        and not flat.rstrip().endswith(('=', 'return'))
                        and not re.search(r'[=\[]\s*[^=]*\]\s*\(', flat)):
                    is_function = True
                    name = m.group(1)
            if is_function:
                first = head.lstrip()
                offset = i - len(head) + (len(head) - len(first))
                line = text.count('\n', 0, offset) + 1
                stack.append((True, name, line))
                depth_in_function += 1
            else:
                stack.append((False, '', 0))
                if depth_in_function:
                    depth_in_function += 1
            head_start = i + 1
        elif c == '}':
            if stack:
                is_function, name, line = stack.pop()
                if depth_in_function:
                    depth_in_function -= 1
                if is_function:
                    end = text.count('\n', 0, i) + 1
                    found.append((name, line, end - line + 1))
            head_start = i + 1
        elif c == ';':
            head_start = i + 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('paths', nargs='*', default=['src', 'tools', 'scenes'])
    parser.add_argument('--top', type=int, default=10)
    parser.add_argument('--over', type=int, default=0)
    args = parser.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    everything = []
    for base in args.paths:
        base = base if os.path.isabs(base) else os.path.join(root, base)
        for folder, _, files in os.walk(base):
            for file in files:
                if file.endswith(SOURCE_SUFFIXES):
                    path = os.path.join(folder, file)
                    for name, line, length in functions(path):
                        everything.append(
                            (length, os.path.relpath(path, root), line, name))
    everything.sort(key=lambda f: (-f[0], f[1], f[2]))
    for length, path, line, name in everything[:args.top]:
        print(f'{length:5d}  {path}:{line}  {name}')
    if args.over and everything and everything[0][0] > args.over:
        too_long = sum(1 for f in everything if f[0] > args.over)
        print(f'{too_long} function(s) longer than {args.over} lines',
              file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
