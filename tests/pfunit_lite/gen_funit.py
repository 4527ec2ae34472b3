#!/usr/bin/env python3
"""Regenerate the type/kind/rank-specific assertions of funit.f90 (pfunit_lite).

Run `python3 gen_funit.py` in this directory: it rewrites the text between the
`! BEGIN GENERATED ...` and `! END GENERATED ...` markers of funit.f90.  Each specific
procedure converts its arguments to flat real64/int64 arrays and calls the hand-written
comparison cores (real_compare, int_compare) of funit.f90.
"""

import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
TARGET = os.path.join(HERE, 'funit.f90')

TYPES = {  # name -> declaration
    'i4': ('integer',),
    'i8': ('integer(int64)',),
    'r4': ('real',),
    'r8': ('real(real64)',),
}
DIMS = {0: '', 1: '(:)', 2: '(:, :)'}

# generic name -> (core, op constant, argument names, keyword enforcer, ranks)
REAL_OPS = [
    ('assertEqual', 'EQ', ('expected', 'actual'), (0, 1, 2)),
    ('assertNotEqual', 'NE', ('expected', 'actual'), (0, 1)),
    ('assertLessThan', 'LT', ('lhs', 'rhs'), (0, 1)),
    ('assertLessThanOrEqual', 'LE', ('lhs', 'rhs'), (0, 1)),
    ('assertGreaterThan', 'GT', ('lhs', 'rhs'), (0, 1)),
    ('assertGreaterThanOrEqual', 'GE', ('lhs', 'rhs'), (0, 1)),
    ('assertRelativelyEqual', 'REL', ('expected', 'actual'), (0, 1, 2)),
]
INT_OPS = [  # as in pFUnit, only assertEqual accepts a positional message
    ('assertEqual', 'EQ', ('expected', 'actual'), False, (0, 1, 2)),
    ('assertNotEqual', 'NE', ('expected', 'actual'), True, (0, 1)),
    ('assertLessThan', 'LT', ('lhs', 'rhs'), True, (0, 1)),
    ('assertLessThanOrEqual', 'LE', ('lhs', 'rhs'), True, (0, 1)),
    ('assertGreaterThan', 'GT', ('lhs', 'rhs'), True, (0, 1)),
    ('assertGreaterThanOrEqual', 'GE', ('lhs', 'rhs'), True, (0, 1)),
]


def flat(var, rank):
    return {0: '[{}]', 1: '{}', 2: 'reshape({0}, [size({0})])'}[rank].format(var)


def operand(var, rank, other, other_rank, real):
    """var (of rank rank) as a flat real64/int64 array shaped like `other`."""
    conv = 'real({}, real64)' if real else 'int({}, int64)'
    if rank == 0 and other_rank > 0:
        return 'spread(%s, 1, size(%s))' % (conv.format(var), other)
    return conv.format(flat(var, rank))


def specific(generic, op, names, ltype, lrank, rtype, rrank, tol, enforcer):
    a, b = names
    short = op.lower()
    name = '%s_%s_%d_%s_%d' % (short, ltype, lrank, rtype, rrank) + ('_' + tol if tol else '')
    real = rtype.startswith('r')
    args = [a, b] + (['tolerance'] if tol else []) + (['unused'] if enforcer else []) + ['message', 'location']
    s = ['   subroutine %s(%s)' % (name, ', '.join(args)),
         '      %s, intent(in) :: %s%s' % (TYPES[ltype][0], a, DIMS[lrank]),
         '      %s, intent(in) :: %s%s' % (TYPES[rtype][0], b, DIMS[rrank])]
    if tol:
        s.append('      %s, intent(in) :: tolerance' % TYPES[tol][0])
    if enforcer:
        s.append('      class(KeywordEnforcer), optional, intent(in) :: unused')
    s += ['      character(len=*), optional, intent(in) :: message',
          '      type(SourceLocation), optional, intent(in) :: location',
          '']
    if enforcer:
        s.append('      if (present(unused)) continue')
    if lrank == rrank and rrank > 0:
        s.append("      if (.not. conformable('%s', shape(%s), shape(%s), message, location)) return"
                 % (generic, a, b))
    left = operand(a, lrank, b, rrank, real)
    right = operand(b, rrank, b, rrank, real)
    if real:
        t = 'real(tolerance, real64)' if tol else '0.0_real64'
        s.append("      call real_compare(OP_%s, '%s', &" % (op, generic))
        s.append('                        %s, &' % left)
        s.append('                        %s, &' % right)
        s.append('                        shape(%s), %s, message, location)' % (b, t))
    else:
        s.append("      call int_compare(OP_%s, '%s', &" % (op, generic))
        s.append('                       %s, &' % left)
        s.append('                       %s, &' % right)
        s.append('                       shape(%s), message, location)' % b)
    s.append('   end subroutine %s' % name)
    return name, '\n'.join(s)


def generate():
    generics = {}
    bodies = []

    def add(generic, name_body):
        generics.setdefault(generic, []).append(name_body[0])
        bodies.append(name_body[1])

    for generic, op, names, ranks in REAL_OPS:
        tols = ['r4', 'r8'] if op == 'REL' else [None, 'r4', 'r8']
        for rrank in ranks:
            lefts = [('r8', rrank), ('r4', rrank), ('i4', rrank)]
            if rrank > 0:
                lefts += [('r8', 0), ('r4', 0), ('i4', 0)]
            for ltype, lrank in lefts:
                for tol in tols:
                    add(generic, specific(generic, op, names, ltype, lrank, 'r8', rrank, tol, False))
    for generic, op, names, enforcer, ranks in INT_OPS:
        for rrank in ranks:
            pairs = [('i4', rrank, 'i4'), ('i8', rrank, 'i8')]
            if rrank == 0:
                pairs.append(('i4', 0, 'i8'))
            else:
                pairs += [('i4', 0, 'i4'), ('i8', 0, 'i8'), ('i4', 0, 'i8')]
            for ltype, lrank, rtype in pairs:
                add(generic, specific(generic, op, names, ltype, lrank, rtype, rrank, None, enforcer))

    interfaces = []
    for generic, names in generics.items():
        interfaces.append('   interface %s' % generic)
        for k in range(0, len(names), 4):
            chunk = ', '.join(names[k:k + 4])
            more = ', &' if k + 4 < len(names) else ''
            prefix = '      module procedure ' if k == 0 else '         '
            interfaces.append(prefix + chunk + more)
        interfaces.append('   end interface %s' % generic)
        interfaces.append('')
    return '\n'.join(interfaces).rstrip() + '\n', '\n\n'.join(bodies) + '\n'


def replace_region(text, tag, content):
    pattern = re.compile(r'(   ! BEGIN GENERATED %s \(gen_funit.py\)\n).*?(   ! END GENERATED %s\n)' % (tag, tag),
                         re.S)
    if not pattern.search(text):
        raise SystemExit('gen_funit.py: markers for %s not found in funit.f90' % tag)
    return pattern.sub(lambda m: m.group(1) + content + m.group(2), text)


def main():
    with open(TARGET, encoding='utf-8') as f:
        text = f.read()
    interfaces, bodies = generate()
    text = replace_region(text, 'INTERFACES', interfaces)
    text = replace_region(text, 'PROCEDURES', '\n' + bodies + '\n')
    with open(TARGET, 'w', encoding='utf-8') as f:
        f.write(text)


if __name__ == '__main__':
    main()
