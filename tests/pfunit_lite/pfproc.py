#!/usr/bin/env python3
"""pfunit_lite preprocessor: turns pFUnit 4 ``.pf`` test files into plain Fortran.

Standard library only.  Three sub-commands (used by pfunit_lite.cmake):

  pfproc.py list   A.pf [B.pf ...]              print the @test names, one per line
  pfproc.py module A.pf OUT.F90                 the test module, directives expanded
  pfproc.py driver --out DRIVER.F90 A.pf [...]  a main program running the tests

Supported subset of the pFUnit syntax:
  * one ``module <name>`` per file, named after the file (as pFUnit assumes);
  * ``@test`` / ``@test(...)`` (options ignored), ``@before``, ``@after``, each
    followed by a module subroutine without arguments;
  * assertion macros at any indentation, alone on their line, possibly continued
    with ``&`` and followed by a comment: @assertEqual, @assertNotEqual,
    @assertRelativelyEqual, @assertTrue, @assertFalse, @assertLessThan,
    @assertLessThanOrEqual, @assertGreaterThan, @assertGreaterThanOrEqual,
    @assertFail, @assertIsFinite, @assertIsNaN, @assertIsInfinite, @assertAll,
    @assertAny, @assertNone, @assertNotAll.
Each macro becomes ``call assertX(<args>, location=SourceLocation('<file>', <line>))``
followed by ``if (anyExceptions()) return``, exactly like pFUnit.  The argument lines
are kept as they are and ``#line`` directives map everything back to the .pf file, so
compiler messages point at the right .pf line.  Any other ``@`` directive is an error.
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


def is_comment_or_blank(line):
    return split_comment(line)[0].strip() == ''


def code_continues(line):
    return split_comment(line)[0].rstrip().endswith('&')


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
                last = self._continuation_end(i)
                if not in_module:
                    self.error(lineno, "directive '@%s' outside the test module" % word)
                if pending:
                    self.error(pending[1], "@%s is not followed by a subroutine" % pending[0])
                if key in MARKERS:
                    rest = self._joined(i, last)[1 + len(word):].strip()
                    if rest and not (rest.startswith('(') and matching_paren(rest, 0) == len(rest) - 1):
                        self.error(lineno, "malformed @%s directive: '%s'" % (key, stripped.strip()))
                    if not after_contains:
                        self.error(lineno, "@%s before the module's 'contains'" % key)
                    pending = (key, lineno)
                    for k in range(i, last + 1):
                        out.append('!' + lines[k])
                elif key in ASSERTIONS:
                    self._expand_assertion(i, last, word, key)
                elif key in UNSUPPORTED:
                    self.error(lineno, "pFUnit directive '@%s' is not supported by pfunit_lite" % word)
                else:
                    self.error(lineno, "unknown directive '@%s'" % word)
                i = last + 1
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

    def _continuation_end(self, i):
        """Index of the last physical line of the statement starting at line i."""
        j = i
        while code_continues(self.lines[j]):
            j += 1
            while j < len(self.lines) and is_comment_or_blank(self.lines[j]):
                j += 1
            if j >= len(self.lines):
                self.error(i + 1, 'continuation runs past the end of the file')
        return j

    def _joined(self, i, last):
        """The statement on lines i..last as one line (comments and '&' removed)."""
        parts = []
        for k in range(i, last + 1):
            code = split_comment(self.lines[k])[0]
            if not code.strip():
                continue
            code = code.rstrip()
            if k > i:
                s = code.lstrip()
                code = s[1:] if s.startswith('&') else code
            if code.endswith('&'):
                code = code[:-1]
            parts.append(code)
        return ''.join(parts).strip()

    # -- assertion expansion -------------------------------------------------------
    def _expand_assertion(self, i, last, word, key):
        lineno = i + 1
        proc, min_args = ASSERTIONS[key]
        text = self._joined(i, last)
        rest = text[1 + len(word):]
        open_at = len(rest) - len(rest.lstrip())
        if not rest[open_at:].startswith('('):
            self.error(lineno, "@%s needs a parenthesised argument list" % word)
        close_at = matching_paren(rest, open_at)
        if close_at < 0:
            self.error(lineno, "unbalanced parentheses in @%s" % word)
        if rest[close_at + 1:].strip():
            self.error(lineno, "unexpected text after @%s(...): '%s'" % (word, rest[close_at + 1:].strip()))
        args = top_level_args(rest[open_at + 1:close_at])
        if any(not a.strip() for a in args):
            self.error(lineno, "empty argument in @%s" % word)
        if len(args) < min_args:
            self.error(lineno, "@%s needs at least %d argument%s"
                       % (word, min_args, '' if min_args == 1 else 's'))

        out = self.output
        code_lines = [k for k in range(i, last + 1) if not is_comment_or_blank(self.lines[k])]
        final = code_lines[-1]
        first_raw = self.lines[i]
        indent = first_raw[:len(first_raw) - len(first_raw.lstrip())]
        at = first_raw.index('@')

        body = {}
        for k in range(i, last + 1):
            body[k] = self.lines[k]
        # Replace the closing ')' of the macro by a continuation '&' (same length).
        code, comment = split_comment(body[final])
        stripped = code.rstrip()
        if not stripped.endswith(')'):
            self.error(final + 1, "@%s: the last line must end with ')'" % word)
        body[final] = stripped[:-1] + '&' + code[len(stripped):] + comment

        first = body[i]
        after_name = first[at + 1 + len(word):]
        call_line = indent + 'call ' + proc + after_name
        self._line_directive(lineno)
        if len(call_line) > MAX_LINE:
            call_line = 'call ' + proc + after_name
        if len(call_line) > MAX_LINE:
            # 'call name' on a line of its own; both lines are numbered as the .pf line.
            out.append(indent + 'call ' + proc + ' &')
            self._line_directive(lineno, force=True)
            call_line = after_name
        out.append(call_line)
        for k in range(i + 1, last + 1):
            out.append(body[k])
        # The added lines carry the number of the macro's last line, so that errors
        # reported at the end of the statement (e.g. no matching specific procedure)
        # point into the macro, not below it.
        self._line_directive(final + 1, force=True)
        sep = ', ' if args else ''
        loc = "%s   & %slocation=SourceLocation(%s, %d))" % (indent, sep, fortran_string(self.name), lineno)
        if len(loc) > MAX_LINE:
            out.append('%s   & %slocation=SourceLocation( &' % (indent, sep))
            out.append('%s   & %s, %d))' % (indent, fortran_string(self.name), lineno))
        else:
            out.append(loc)
        out.append(indent + 'if (anyExceptions()) return')
        self._line_directive(last + 2)

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


def driver_text(files):
    lines = ['! Generated by pfunit_lite/pfproc.py from %s -- do not edit.'
             % ', '.join(tf.name for tf in files),
             'program pfunit_lite_driver',
             '   use funit, only: funit_lite_init, funit_lite_run, funit_lite_finish']
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
    lines.append('   call funit_lite_init()')
    lines.extend(calls)
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
            files = [TestFile(p) for p in args[2:]]
            check_unique(files)
            write_file(args[1], driver_text(files))
        else:
            return usage()
    except PfError as e:
        sys.stderr.write('pfunit_lite: %s\n' % e)
        return 1
    except OSError as e:
        sys.stderr.write('pfunit_lite: %s\n' % e)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
