#!/usr/bin/env python3
"""Prints the programs (CMake targets) that a build folder's tests of some labels run.

usage: test-programs.py BUILD_DIR LABEL_REGEX EXCLUDE_NAME_REGEX

Read from the CTestTestfile.cmake files CMake wrote, so that it works before anything is
built (ctest -N shows no command for a program that does not exist yet). A program's file
name is its target's name in this project.
"""
import os
import re
import sys


def main():
    build, labels, exclude = sys.argv[1], re.compile(sys.argv[2]), re.compile(sys.argv[3])
    programs = {}
    test_labels = {}
    for folder, _, files in os.walk(build):
        if "CTestTestfile.cmake" not in files:
            continue
        with open(os.path.join(folder, "CTestTestfile.cmake"), encoding="utf-8") as f:
            for line in f:
                added = re.match(r'add_test\(([^ ]+) "([^"]+)"', line)
                if added:
                    programs[added.group(1)] = os.path.basename(added.group(2))
                labelled = re.match(r'set_tests_properties\(([^ ]+) PROPERTIES .*LABELS "([^"]*)"', line)
                if labelled:
                    test_labels[labelled.group(1)] = labelled.group(2).split(";")
    names = set()
    for test, program in programs.items():
        if exclude.search(test):
            continue
        if any(labels.fullmatch(label) for label in test_labels.get(test, [])):
            names.add(program)
    print("\n".join(sorted(names)))
    return 0 if names else 1


if __name__ == "__main__":
    sys.exit(main())
