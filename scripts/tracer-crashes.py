#!/usr/bin/env python3
"""Tells LeakSanitizer's tracer crashes from real failures in a ctest run.

usage: scripts/tracer-crashes.py RESULTS.xml (ctest --output-junit)

LeakSanitizer's own tracer now and then crashes at exit while it stops
TBB's threads ("Tracer caught signal 11", "LeakSanitizer has encountered a
fatal error"), failing a test that passed. A failed test counts as such a
crash only when its output shows the tracer's message and nothing else
went wrong: no failed GoogleTest assertion, no sanitizer report.

Exits 0 and prints a ctest -R regex of exactly the failed tests when every
failure is a tracer crash (nothing when none failed); exits 1 and names
the other failures otherwise.
"""
import re
import sys
import xml.etree.ElementTree as ElementTree

TRACER_CRASH = ('LeakSanitizer has encountered a fatal error',
                'Tracer caught signal')
REAL_FAILURE = ('[  FAILED  ]',
                'ERROR: AddressSanitizer',
                'ERROR: LeakSanitizer: detected memory leaks',
                'runtime error:',
                'FAILED:')


def is_tracer_crash(output):
    return (any(m in output for m in TRACER_CRASH)
            and not any(m in output for m in REAL_FAILURE))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    suite = ElementTree.parse(sys.argv[1]).getroot()
    crashed, failed = [], []
    for case in suite.iter('testcase'):
        if case.get('status') in ('run', 'disabled'):
            continue
        output = case.findtext('system-out') or ''
        (crashed if is_tracer_crash(output) else failed).append(
            case.get('name'))
    if failed:
        print('failed (not a LeakSanitizer tracer crash): '
              + ', '.join(failed), file=sys.stderr)
        sys.exit(1)
    if crashed:
        print('^(' + '|'.join(re.escape(name) for name in crashed) + ')$')


if __name__ == '__main__':
    main()
