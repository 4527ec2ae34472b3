#!/usr/bin/env python3
"""pfunit_lite preprocessor: turns pFUnit 4 ``.pf`` test files into plain Fortran.

Standard library only.  Three sub-commands (used by pfunit_lite.cmake):

  pfproc.py list   A.pf [B.pf ...]              print the @test names, one per line
  pfproc.py module A.pf OUT.F90                 the test module, directives expanded
  pfproc.py driver --out DRIVER.F90 [--extra-use M] [--extra-initialize P]
                   [--extra-finalize P] A.pf [...]   a main program running the tests

As in pFUnit's driver, --extra-use names a module the driver uses, --extra-initialize a
subroutine without arguments called before any test runs (not for --list), and
--extra-finalize one called after the last test.

Supported subset of the pFUnit syntax:
  * one ``module <name>`` per file, named after the file (as pFUnit assumes);
  * ``@test`` / ``@test(...)`` (options ignored), ``@before``, ``@after``, each
    followed by a module subroutine without arguments;
  * assertion macros at any indentation, alone on their line: @assertEqual,
    @assertNotEqual, @assertRelativelyEqual, @assertTrue, @assertFalse, @assertLessThan,
    @assertLessThanOrEqual, @assertGreaterThan, @assertGreaterThanOrEqual,
    @assertFail, @assertIsFinite, @assertIsNaN, @assertIsInfinite, @assertAll,
    @assertAny, @assertNone, @assertNotAll.
Each macro becomes ``call assertX(<args>, location=SourceLocation('<file>', <line>))``
followed by ``if (anyExceptions()) return``, exactly like pFUnit.  ``#line`` directives
map everything back to the .pf file, so compiler messages point at the right .pf line.
Any other ``@`` directive is an error.

Refused exactly where pFUnit 4.14 refuses (its funitproc passes such a line through
unchanged, or writes a line gfortran rejects, or stops), each with one message
``<file>.pf:<line>: error: ...`` and exit status 1:
  * a directive continued with ``&`` (funitproc recognises a directive on one line only);
  * a ``! comment`` after a directive (the line then no longer ends with ``)``);
  * a directive whose generated Fortran line is longer than 132 columns (funitproc
    writes ``  call assert<name>(<arguments>, &`` from it, without the indentation);
  * a module not named after its file (ignoring case).
"""

import os
import re
import sys

# lower-case directive -> (Fortran procedure, minimum number of arguments)
ASSERTIONS = {
    'assertequal': ('assertEqual', 2),
    'assertnotequal': ('assertNotEqual', 2),
    'assertrelativelyequal': ('assertRelativelyEqual', 3),
    'asserttrue': ('assertTrue', 1),
    'assertfalse': ('assertFalse', 1),
    'assertlessthan': ('assertLessThan', 2),
    'assertlessthanorequal': ('assertLessThanOrEqual', 2),
    'assertgreaterthan': ('assertGreaterThan', 2),
    'assertgreaterthanorequal': ('assertGreaterThanOrEqual', 2),
    'assertfail': ('assertFail', 1),
    'assertisfinite': ('assertIsFinite', 1),
    'assertisnan': ('assertIsNaN', 1),
    'assertisinfinite': ('assertIsInfinite', 1),
    'assertall': ('assertAll', 1),
    'assertany': ('assertAny', 1),
    'assertnone': ('assertNone', 1),
    'assertnotall': ('assertNotAll', 1),
}
MARKERS = ('test', 'before', 'after')
# pFUnit directives that exist but are deliberately not supported here.
UNSUPPORTED = ('testcase', 'testparameter', 'suite', 'mpitest', 'mpiassert', 'disable',
               'assertexceptionraised', 'assertassociated', 'assertnotassociated',
               'assertunassociated', 'assertequaluserdefined', 'assertismemberof',
               'assertcontains', 'assertispermutationof', 'assertsameshape',
               'assertisnotnan')

MAX_LINE = 132  # Fortran 2008 free-form limit (gfortran default)

MODULE_RE = re.compile(r'^\s*module\s+(\w+)\s*$', re.I)
END_MODULE_RE = re.compile(r'^\s*end\s*module\b', re.I)
CONTAINS_RE = re.compile(r'^\s*contains\s*$', re.I)
SUBROUTINE_RE = re.compile(
    r'^\s*(?:(?:recursive|impure|non_recursive|module)\s+)*subroutine\s+(\w+)\s*(?:\((.*)\))?\s*$',
    re.I)
DIRECTIVE_RE = re.compile(r'@(\w+)')
MIDLINE_RE = re.compile(r'@(assert\w*|test|before|after)\b', re.I)


class PfError(Exception):
    def __init__(self, path, line, message):
        Exception.__init__(self, '%s:%d: error: %s' % (path, line, message))


def split_comment(line):
    """(code, comment) of one physical line; quotes are respected."""
    quote = None
    i = 0
    while i < len(line):
        c = line[i]
        if quote:
            if c == quote:
                if i + 1 < len(line) and line[i + 1] == quote:
                    i += 1  # doubled quote inside a string
                else:
                    quote = None
        elif c in '\'"':
            quote = c
        elif c == '!':
            return line[:i], line[i:]
        i += 1
    return line, ''


def top_level_args(text):
    """Split an argument list on commas outside strings and brackets."""
    args, depth, quote, start = [], 0, None, 0
    i = 0
    while i < len(text):
        c = text[i]
        if quote:
            if c == quote:
                if i + 1 < len(text) and text[i + 1] == quote:
                    i += 1
                else:
                    quote = None
        elif c in '\'"':
            quote = c
        elif c in '([':
            depth += 1
        elif c in ')]':
            depth -= 1
        elif c == ',' and depth == 0:
            args.append(text[start:i])
            start = i + 1
        i += 1
    args.append(text[start:])
    if len(args) == 1 and not args[0].strip():
        return []
    return args


def matching_paren(text, open_at):
    """Index of the ')' closing the '(' at open_at, or -1."""
    depth, quote = 0, None
    i = open_at
    while i < len(text):
        c = text[i]
        if quote:
            if c == quote:
                if i + 1 < len(text) and text[i + 1] == quote:
                    i += 1
                else:
                    quote = None
        elif c in '\'"':
            quote = c
        elif c == '(':
            depth += 1
        elif c == ')':
            depth -= 1
            if depth == 0:
                return i
        i += 1
    return -1


def fortran_string(s):
    return "'" + s.replace("'", "''") + "'"


def cpp_string(s):
    return '"' + s.replace('\\', '\\\\').replace('"', '\\"') + '"'


class TestFile:
    """One parsed .pf file."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.name = os.path.basename(path)
        self.stem = os.path.splitext(self.name)[0]
        with open(path, encoding='utf-8', errors='replace') as f:
            self.lines = f.read().splitlines()
        self.module = None
        self.tests = []       # (name, line)
        self.before = None
        self.after = None
        self.output = []      # generated Fortran lines
        self._parse()

    def error(self, line, message):
        raise PfError(self.path, line, message)

    # -- parsing --------------------------------------------------------------------
    def _parse(self):
        lines = self.lines
        out = self.output
        out.append('#line 1 ' + cpp_string(self.path))
        in_module = False
        after_contains = False
        module_done = False
        pending = None  # (kind, line) of an @test/@before/@after awaiting its subroutine
        i = 0
        while i < len(lines):
            raw = lines[i]
            lineno = i + 1
            stripped = raw.lstrip()
            if stripped.startswith('@'):
                m = DIRECTIVE_RE.match(stripped)
                word = m.group(1) if m else ''
                key = word.lower()
                self._check_one_line(i, word)
                if not in_module:
                    self.error(lineno, "directive '@%s' outside the test module" % word)
                if pending:
                    self.error(pending[1], "@%s is not followed by a subroutine" % pending[0])
                if key in MARKERS:
                    rest = stripped.strip()[1 + len(word):].strip()
                    if rest and not (rest.startswith('(') and matching_paren(rest, 0) == len(rest) - 1):
                        self.error(lineno, "malformed @%s directive: '%s'" % (key, stripped.strip()))
                    if not after_contains:
                        self.error(lineno, "@%s before the module's 'contains'" % key)
                    pending = (key, lineno)
                    out.append('!' + raw)
                elif key in ASSERTIONS:
                    self._expand_assertion(i, word, key)
                elif key in UNSUPPORTED:
                    self.error(lineno, "pFUnit directive '@%s' is not supported by pfunit_lite" % word)
                else:
                    self.error(lineno, "unknown directive '@%s'" % word)
                i += 1
                continue

            code = split_comment(raw)[0]
            if code.strip():
                mid = MIDLINE_RE.search(self._blank_strings(code))
                if mid:
                    self.error(lineno, "directive '@%s' must start its line" % mid.group(1))
                if pending:
                    m = SUBROUTINE_RE.match(code)
                    if not m:
                        self.error(lineno, "@%s must be followed by 'subroutine <name>()' (found: '%s')"
                                   % (pending[0], code.strip()))
                    name, args = m.group(1), (m.group(2) or '').strip()
                    if args:
                        self.error(lineno, "test procedure '%s' must have no arguments "
                                   "(@testcase-style tests are not supported by pfunit_lite)" % name)
                    self._register(pending[0], name, lineno)
                    pending = None
                elif not in_module:
                    m = MODULE_RE.match(code)
                    if m and m.group(1).lower() not in ('procedure', 'subroutine', 'function'):
                        if module_done:
                            self.error(lineno, 'only one module per .pf file is supported')
                        self.module = m.group(1)
                        if self.module.lower() != self.stem.lower():
                            self.error(lineno, "module '%s' must be named after its file ('%s'), "
                                       "as pFUnit's add_pfunit_ctest assumes" % (self.module, self.stem))
                        in_module = True
                elif CONTAINS_RE.match(code) and not after_contains:
                    after_contains = True
                elif END_MODULE_RE.match(code):
                    in_module = False
                    module_done = True
            out.append(raw)
            i += 1
        if pending:
            self.error(pending[1], "@%s is not followed by a subroutine" % pending[0])
        if self.module is None:
            self.error(1, "no 'module <name>' found")
        if in_module:
            self.error(len(lines), "module '%s' is not closed by 'end module'" % self.module)

    @staticmethod
    def _blank_strings(code):
        """The code with string contents blanked, for the mid-line directive check."""
        res, quote = [], None
        for c in code:
            if quote:
                res.append(' ')
                if c == quote:
                    quote = None
            else:
                res.append(c)
                if c in '\'"':
                    quote = c
        return ''.join(res)

    def _register(self, kind, name, lineno):
        if kind == 'test':
            for other, line in self.tests:
                if other.lower() == name.lower():
                    self.error(lineno, "duplicate test '%s' (first at line %d)" % (name, line))
            self.tests.append((name, lineno))
        elif kind == 'before':
            if self.before:
                self.error(lineno, 'only one @before procedure is allowed')
            self.before = name
        else:
            if self.after:
                self.error(lineno, 'only one @after procedure is allowed')
            self.after = name

    def _check_one_line(self, i, word):
        """Refuse what pFUnit's funitproc does not recognise as a directive: a continued
        line or a comment after it (its patterns need the line to end in the directive)."""
        code, comment = split_comment(self.lines[i])
        if code.rstrip().endswith('&'):
            self.error(i + 1, "@%s is continued with '&': pFUnit recognises a directive only "
                       "on one line (put long operands in local variables)" % word)
        if comment:
            self.error(i + 1, "comment after @%s: pFUnit does not recognise a directive "
                       "followed by '%s' (put the comment on the line above)"
                       % (word, comment.strip()[:40]))

    def _check_generated_length(self, lineno, word, args):
        """Refuse a directive whose lines as written by pFUnit's funitproc exceed 132
        columns: '  call assert<name>(<args>, &', then the location lines."""
        lines = ['  call %s(%s%s&' % (word, args, ', ' if args.strip() else ''),
                 " & location=SourceLocation( &",
                 " & '%s', &" % self.name,
                 ' & %d) )' % lineno]
        for text in lines:
            if len(text) > MAX_LINE:
                self.error(lineno, "@%s generates a Fortran line of %d columns under pFUnit "
                           "(limit %d): '%s...'; put long operands in local variables"
                           % (word, len(text), MAX_LINE, text.strip()[:40]))

    # -- assertion expansion -------------------------------------------------------
    def _expand_assertion(self, i, word, key):
        """The assertion on line i, laid out as pFUnit's funitproc writes it."""
        lineno = i + 1
        proc, min_args = ASSERTIONS[key]
        rest = self.lines[i].strip()[1 + len(word):]
        open_at = len(rest) - len(rest.lstrip())
        if not rest[open_at:].startswith('('):
            self.error(lineno, "@%s needs a parenthesised argument list" % word)
        close_at = matching_paren(rest, open_at)
        if close_at < 0:
            self.error(lineno, "unbalanced parentheses in @%s" % word)
        if rest[close_at + 1:].strip():
            self.error(lineno, "unexpected text after @%s(...): '%s'" % (word, rest[close_at + 1:].strip()))
        inner = rest[open_at + 1:close_at]
        args = top_level_args(inner)
        if any(not a.strip() for a in args):
            self.error(lineno, "empty argument in @%s" % word)
        if len(args) < min_args:
            self.error(lineno, "@%s needs at least %d argument%s"
                       % (word, min_args, '' if min_args == 1 else 's'))
        self._check_generated_length(lineno, word, inner)

        out = self.output
        self._line_directive(lineno)
        out.append('  call %s(%s%s&' % (proc, inner, ', ' if args else ''))
        out.append(' & location=SourceLocation( &')
        out.append(' & %s, &' % fortran_string(self.name))
        out.append(' & %d) )' % lineno)
        out.append('  if (anyExceptions()) return')
        self._line_directive(lineno + 1)

    def _line_directive(self, number, force=False):
        """Emit '#line number', unless the previous output line is the same directive."""
        directive = '#line %d %s' % (number, cpp_string(self.path))
        if force or not self.output or self.output[-1] != directive:
            self.output.append(directive)


# -- outputs -----------------------------------------------------------------------
def write_file(path, text):
    """Write text to path (always, so that the output is newer than its inputs)."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, 'w', encoding='utf-8') as f:
        f.write(text)


def module_text(tf):
    header = '! Generated by pfunit_lite/pfproc.py from %s -- do not edit.\n' % tf.name
    return header + '\n'.join(tf.output) + '\n'


def check_unique(files):
    seen = {}
    for tf in files:
        for name, line in tf.tests:
            key = name.lower()
            if key in seen:
                raise PfError(tf.path, line, "test '%s' already defined in %s" % (name, seen[key]))
            seen[key] = tf.name


def driver_text(files, extra=None):
    extra = extra or {}
    lines = ['! Generated by pfunit_lite/pfproc.py from %s -- do not edit.'
             % ', '.join(tf.name for tf in files),
             'program pfunit_lite_driver',
             '   use funit, only: funit_lite_init, funit_lite_run, funit_lite_finish']
    if extra.get('use'):
        lines.append('   use %s' % extra['use'])
    calls = []
    for n, tf in enumerate(files, 1):
        renames = []
        for m, (name, _) in enumerate(tf.tests, 1):
            renames.append('pfl_%d_%d => %s' % (n, m, name))
        hooks = {}
        if tf.before and tf.tests:
            renames.append('pfl_%d_before => %s' % (n, tf.before))
            hooks['before'] = 'pfl_%d_before' % n
        if tf.after and tf.tests:
            renames.append('pfl_%d_after => %s' % (n, tf.after))
            hooks['after'] = 'pfl_%d_after' % n
        if renames:
            lines.append('   use %s, only: &' % tf.module)
            for k, r in enumerate(renames):
                lines.append('      ' + r + (', &' if k < len(renames) - 1 else ''))
        else:
            lines.append('   use %s, only:' % tf.module)
        for m, (name, _) in enumerate(tf.tests, 1):
            call = ['   call funit_lite_run(%s, &' % fortran_string(tf.module),
                    '      %s, &' % fortran_string(name),
                    '      pfl_%d_%d' % (n, m)]
            for hook in ('before', 'after'):
                if hook in hooks:
                    call[-1] += ', &'
                    call.append('      %s=%s' % (hook, hooks[hook]))
            call[-1] += ')'
            calls.extend(call)
    lines.append('   implicit none')
    lines.append('')
    if extra.get('initialize'):
        lines.append('   call funit_lite_init(%s)' % extra['initialize'])
    else:
        lines.append('   call funit_lite_init()')
    lines.extend(calls)
    if extra.get('finalize'):
        lines.append('   call funit_lite_finish(%s)' % extra['finalize'])
    else:
        lines.append('   call funit_lite_finish()')
    lines.append('end program pfunit_lite_driver')
    return '\n'.join(lines) + '\n'


def usage():
    sys.stderr.write(__doc__)
    return 2


def main(argv):
    if len(argv) < 2:
        return usage()
    cmd, args = argv[1], argv[2:]
    try:
        if cmd == 'list' and args:
            files = [TestFile(p) for p in args]
            check_unique(files)
            for tf in files:
                for name, _ in tf.tests:
                    sys.stdout.write(name + '\n')
        elif cmd == 'module' and len(args) == 2:
            write_file(args[1], module_text(TestFile(args[0])))
        elif cmd == 'driver' and len(args) >= 3 and args[0] == '--out':
            out, rest, extra = args[1], args[2:], {}
            while len(rest) >= 2 and rest[0] in ('--extra-use', '--extra-initialize',
                                                 '--extra-finalize'):
                extra[rest[0][len('--extra-'):]] = rest[1]
                rest = rest[2:]
            if not rest:
                return usage()
            files = [TestFile(p) for p in rest]
            check_unique(files)
            write_file(out, driver_text(files, extra))
        else:
            return usage()
    except PfError as e:
        sys.stderr.write('%s\n' % e)
        return 1
    except OSError as e:
        sys.stderr.write('pfunit_lite: %s\n' % e)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
