"""Lists functions longer than a limit in C++ sources (a brace count, not a parser: a definition is a
line outside any function that ends with ') {' (or ') const {', a trailing return type, an initialiser
list's '{'), and the function runs to its matching brace). Usage: function_lengths.py LIMIT DIR...
Exits 1 if any function is longer than LIMIT lines."""
import pathlib
import re
import sys

DEFINITION = re.compile(r'\)\s*(const)?\s*(noexcept)?\s*(override)?\s*(->\s*[\w:<>, ]+)?\s*\{\s*$')
NOT_A_FUNCTION = re.compile(r'\s*(namespace|struct|class|enum|union|if|for|while|switch|else|do)\b')


def code_of(line):
    line = re.sub(r'"([^"\\]|\\.)*"', '""', line)
    line = re.sub(r"'([^'\\]|\\.)'", "''", line)
    return re.sub(r'//.*', '', line)


def long_functions(path, limit):
    lines = path.read_text().split('\n')
    depth, start, start_depth, found = 0, None, None, []
    for number, line in enumerate(lines):
        code = code_of(line)
        if start is None and DEFINITION.search(code) and not NOT_A_FUNCTION.match(code):
            start, start_depth = number, depth
        depth += code.count('{') - code.count('}')
        if start is not None and depth <= start_depth:
            length = number - start + 1
            if length > limit:
                found.append((length, f'{path}:{start + 1}', lines[start].strip()[:80]))
            start = None
    return found


def main():
    limit = int(sys.argv[1])
    found = []
    for directory in sys.argv[2:]:
        for path in sorted(pathlib.Path(directory).rglob('*.[ch]pp')):
            found += long_functions(path, limit)
    for length, where, text in sorted(found, reverse=True):
        print(f'{where}: {length} lines: {text}')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
