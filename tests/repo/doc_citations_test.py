#!/usr/bin/env python3
"""Repository.DocumentsCiteWhatExists: every file path and every function name that a document
cites exists in the repository.

Documents: the tracked markdown files under docs/ and every tracked README.md (the root's
included). Inside a fenced code block nothing is checked; elsewhere the citations are the
words of inline code spans (`...`, split at white space) and the targets of markdown links.

File paths. A word is a path when it contains a '/' or ends in one of EXTENSIONS. A link
target (its #anchor removed) must exist relative to the document's folder, as markdown
resolves it. A code word must exist relative to the document's folder or to the repository
root; a bare file name (no '/') may also name a tracked file in any folder (documents write
`lights.hpp` inside a paragraph about bake/lighting/), and a relative path may also be the
tail of a tracked path in a subfolder of the document's folder (tests/README.md writes
`lab/error_budget_test.cpp` for tests/lab/error_budget_test.cpp). Globs (* ? [ ]) and brace
lists ({a,b}) must match something; a path without an extension may name a file's stem
(`bake/shard_plan` for shard_plan.hpp and .cpp). Not checked, by rule:
  - URLs, absolute paths (/usr/share/..., /proc/...) and ~ paths: not in the repository;
  - command-line options and their values (a word starting with '-', or the word after an
    option such as `--shard i/N`): they are not paths;
  - templates: a path with a placeholder, an upper-case word such as NAME, DIR, MAP, I
    (`maps/NAME.bsp`, `logs/shard-I.job-J.log`), or <...>, or `...`;
  - paths inside an archive (after `.pk3:`), and build or run outputs, whose first component is
    one of OUTPUT_FOLDERS (build/, out/, captures/; build-fuzz/ and build*/ too);
  - a bare extension (`.gltf`, `*.olpak`), and words that start with a digit (`1/k`);
  - the few words in NOT_PATHS, with the reason beside each.

Function names. A code span that begins with a (possibly qualified) name followed by '(' --
`name(`, `name(args)`, `ns::Type::name(...)` -- or that is a qualified name `A::b`, cites
each identifier of that name, and each must occur as an identifier in a source file (EXTENSIONS_CODE)
or build file (CMakeLists.txt, *.cmake) that git tracks.

Each broken citation is printed as FILE:LINE: cites PATH which does not exist; the test fails
if there is any. Without git or a .git folder it is skipped (exit 77).
Usage: doc_citations_test.py [REPOSITORY_ROOT]
"""
import fnmatch
import os
import re
import subprocess
import sys

SKIP = 77
EXTENSIONS = ('.cpp', '.hpp', '.h', '.glsl', '.frag', '.vert', '.comp', '.inc', '.md', '.sh',
              '.py', '.txt', '.json', '.gltf', '.replay', '.cmake')
EXTENSIONS_CODE = ('.cpp', '.hpp', '.h', '.glsl', '.frag', '.vert', '.comp', '.inc')
OUTPUT_FOLDERS = ('build', 'out', 'captures')
# Words that look like paths but are not files of the repository (keep this list short).
NOT_PATHS = {
    'task/none': 'a Slurm setting (TaskPlugin=task/none)',
    'proctrack/linuxproc': 'a Slurm setting (ProctrackType=proctrack/linuxproc)',
    'node/mesh': 'a glTF node with a mesh',
    'xdg/': 'the XDG user folders',
    'report.json': 'a file the baker writes (--report)',
    'manifest.json': 'a file the Slurm bake writes in its work folder',
    'merge.sh': 'a batch script the Slurm bake writes in its work folder',
    'level.gltf': 'the example level of a data-flow diagram',
    'scripts/*.shader': 'the Quake 3 shader scripts inside a map\'s pk3',
    'base/': 'the folder of Sascha Willems\' Vulkan examples',
}


def tracked_files(root):
    out = subprocess.run(['git', '-C', root, 'ls-files', '-z'], capture_output=True, check=True)
    return [f for f in out.stdout.decode('utf-8', 'replace').split('\0') if f]


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..', '..')
    root = os.path.abspath(root)
    if not os.path.exists(os.path.join(root, '.git')):
        print(f'SKIP: {root} has no .git (not a git checkout); cannot list the tracked files')
        return SKIP
    try:
        files = tracked_files(root)
    except (OSError, subprocess.CalledProcessError) as e:
        print(f'SKIP: git ls-files failed in {root}: {e}')
        return SKIP
    files = [f for f in files if os.path.isfile(os.path.join(root, f))]

    paths = set(files)  # tracked files and every folder above one
    for f in files:
        d = os.path.dirname(f)
        while d and d not in paths:
            paths.add(d)
            d = os.path.dirname(d)
    basenames = {os.path.basename(p) for p in paths}

    identifiers = set()
    for f in files:
        if f.endswith(EXTENSIONS_CODE + ('.cmake', 'CMakeLists.txt')):
            with open(os.path.join(root, f), encoding='utf-8', errors='replace') as fh:
                identifiers.update(re.findall(r'[A-Za-z_]\w*', fh.read()))

    documents = [f for f in files if f.endswith('.md') and
                 (f.startswith('docs/') or os.path.basename(f) == 'README.md')]

    def norm(p):
        p = os.path.normpath(p)
        return '' if p == '.' else p

    def exists(p):
        p = norm(p)
        if p.startswith('..'):
            return False
        if p == '':
            return True
        if re.search(r'[*?\[{]', p):
            alternatives = [p]
            while any('{' in a for a in alternatives):  # expand {a,b}
                expanded = []
                for a in alternatives:
                    m = re.search(r'\{([^{}]*)\}', a)
                    if not m:
                        expanded.append(a.replace('{', ''))
                        continue
                    for choice in m.group(1).split(','):
                        expanded.append(a[:m.start()] + choice + a[m.end():])
                alternatives = expanded
            return any(fnmatch.filter(paths, a) for a in alternatives)
        if p in paths:
            return True
        # An extensionless path may name a file's stem: `bake/bake_level` for bake_level.cpp/.hpp.
        return not os.path.splitext(p)[1] and bool(fnmatch.filter(paths, p + '.*'))

    def path_ok(doc, word, link):
        folder = os.path.dirname(doc)
        target = word.rstrip('/')
        if link:
            return exists(os.path.join(folder, target))
        if exists(os.path.join(folder, target)) or exists(target):
            return True
        if '/' not in target:
            return target in basenames or exists('*/' + target)
        if folder and not target.startswith(('./', '../')):
            return exists(folder + '/*/' + target) or exists(folder + '/*/*/' + target)
        return False

    def is_template(word):
        return (re.search(r'(^|[^A-Za-z])[A-Z][A-Z0-9_]*($|[^A-Za-z])', word) or '<' in word
                or '...' in word or '…' in word)

    def path_words(span):
        """The words of a code span that are paths to check."""
        previous = ''
        for raw in span.split():
            word = raw.strip('"\'(),;')
            after_option = previous.startswith('-')
            previous = word
            if not word or word.startswith('-') or after_option:
                continue
            if '://' in word or word.startswith(('/', '~', '$')):
                continue
            if '.pk3:' in word:
                continue
            if '=' in word:
                continue
            word = word.rstrip('.:')
            if not ('/' in word or word.endswith(EXTENSIONS)):
                continue
            if word in NOT_PATHS or word.rstrip('/') + '/' in NOT_PATHS:
                continue
            if is_template(word):
                continue
            if re.sub(r'[-*].*', '', word.lstrip('./').split('/')[0]) in OUTPUT_FOLDERS:
                continue
            if re.fullmatch(r'\*?\.\w+', word) or re.match(r'\d', word):
                continue  # an extension (`.gltf`), a number or a fraction (`1/k`)
            yield word

    name_re = re.compile(r'(~?[A-Za-z_]\w*(?:(?:::|\.|->)~?[A-Za-z_]\w*)*)(\(|$)')

    problems = 0
    checked = 0
    for doc in documents:
        with open(os.path.join(root, doc), encoding='utf-8', errors='replace') as fh:
            lines = fh.read().split('\n')
        fenced = False
        for number, line in enumerate(lines, 1):
            if line.lstrip().startswith(('```', '~~~')):
                fenced = not fenced
                continue
            if fenced:
                continue
            for m in re.finditer(r'\]\(([^)\s]+)(?:\s+"[^"]*")?\)', line):
                target = m.group(1).split('#')[0]
                if not target or '://' in target or target.startswith('mailto:'):
                    continue
                checked += 1
                if not path_ok(doc, target, link=True):
                    print(f'{doc}:{number}: cites {target} which does not exist')
                    problems += 1
            for m in re.finditer(r'(`+)(.+?)\1', line):
                span = m.group(2).strip()
                for word in path_words(span):
                    checked += 1
                    if not path_ok(doc, word, link=False):
                        print(f'{doc}:{number}: cites {word} which does not exist')
                        problems += 1
                f = name_re.match(span)
                if f and (f.group(2) == '(' or '::' in f.group(1)):
                    for name in re.split(r'::|\.|->', f.group(1)):
                        checked += 1
                        if name.lstrip('~') not in identifiers:
                            print(f'{doc}:{number}: cites {f.group(1)}'
                                  f'{"()" if f.group(2) else ""} which does not exist'
                                  f' (no identifier {name} in the sources)')
                            problems += 1
    if problems:
        print(f'FAIL: {problems} citation(s) above name a file, folder or function that does not '
              f'exist ({len(documents)} documents, {checked} citations checked); fix the document, '
              f'or see the rules at the top of {os.path.relpath(__file__, root)}')
        return 1
    print(f'OK: {len(documents)} documents, {checked} citations of files, folders and functions, '
          f'all exist')
    return 0


if __name__ == '__main__':
    sys.exit(main())
