"""Optional comparison with OpenSeesPy (issue 26): the realised coefficient of restitution of
a central impact of two free masses on pound's smooth laws (the listing's "realised e",
pound_law_impact) and on OpenSees' uniaxial materials of the same laws, in a zeroLength
element stepped by Newmark's average acceleration at a small dt.

    /path/to/python-with-openseespy scripts/opensees_laws.py [POUND_EXE]

Known differences (stated, not errors): OpenSees' Hertzdamp does not clip its force (it would
pull where 1 + a d'/v0 < 0 while separating, which at e = 0.65 does not happen: a e_r < 1) and
takes the pre-impact speed from its own state; ViscoelasticGap keeps tension (it rebounds with exactly
the e of Anagnostopoulos' xi, where pound's clipped kelvin gives more); JankowskiImpact is the
same law as pound's jankowski.
"""
import math
import os
import re
import subprocess
import sys
import tempfile

import openseespy.opensees as ops

M1, M2, V0 = 10.0, 30.0, 0.5          # t, t, m/s
E = 0.65
K_KELVIN, K_HERTZ = 1.0e6, 2.75e6     # kN/m, kN/m^(3/2)


def opensees_restitution(material, dt=1.0e-6, t_max=0.2):
    """Separation speed / approach speed of the two masses on `material` (a zeroLength)."""
    ops.wipe()
    ops.model('basic', '-ndm', 1, '-ndf', 1)
    ops.node(1, 0.0, '-mass', M1)
    ops.node(2, 0.0, '-mass', M2)
    ops.uniaxialMaterial(*material)
    ops.element('zeroLength', 1, 1, 2, '-mat', material[1], '-dir', 1)
    ops.setNodeVel(1, 1, V0 * M2 / (M1 + M2), '-commit')
    ops.setNodeVel(2, 1, -V0 * M1 / (M1 + M2), '-commit')
    ops.constraints('Plain')
    ops.numberer('Plain')
    ops.system('FullGeneral')
    ops.test('NormDispIncr', 1.0e-12, 100)
    ops.algorithm('Newton')
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    t, started = 0.0, False
    while t < t_max:
        if ops.analyze(1, dt) != 0:
            return float('nan')
        t += dt
        d = ops.nodeDisp(1, 1) - ops.nodeDisp(2, 1)
        started = started or d > 0.0
        if started and d <= 0.0:
            break
    return -(ops.nodeVel(1, 1) - ops.nodeVel(2, 1)) / V0


def pound_restitution(exe, law, stiffness):
    """The listing's realised e of pound's law between two one-storey buildings of M1, M2."""
    deck = f"""&analysis dt = 0.01, t_end = 0.1 /
&ground kind = 'pulse', x0 = 0.001, a = 2.0, b = 12.0 /
&building name = 'A', n_storeys = 1, height = 3.0, mass = {M1}, stiffness = 1.0e4 /
&building name = 'B', n_storeys = 1, height = 3.0, mass = {M2}, stiffness = 1.0e4 /
&contact left = 'A', right = 'B', floors_left = 1, floors_right = 1, gap = 0.01,
  law = '{law}', stiffness = {stiffness}, restitution = {E} /
"""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, 'impact.nml')
        open(path, 'w').write(deck)
        subprocess.run([exe, path, '-o', tmp, '--quiet'], check=True, capture_output=True)
        text = open(os.path.join(tmp, 'impact.out')).read()
    return float(re.search(r"realised e = ([0-9.Ee+-]+)", text).group(1))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, '..', 'build', 'release', 'pound')
    meff = M1 * M2 / (M1 + M2)
    xi_a = -math.log(E) / math.sqrt(math.pi ** 2 + math.log(E) ** 2)
    xi_j = 9.0 * math.sqrt(5.0) * (1.0 - E * E) / (2.0 * E * (E * (9.0 * math.pi - 16.0) + 16.0))
    a = 8.0 * (1.0 - E) / (5.0 * E)
    rows = [
        ('jankowski', K_HERTZ, ['JankowskiImpact', 1, K_HERTZ, xi_j, meff, -1.0e-12], 'JankowskiImpact'),
        ('hertz_damp', K_HERTZ, ['Hertzdamp', 1, K_HERTZ, a, -1.0e-12], 'Hertzdamp (no clip)'),
        ('kelvin', K_KELVIN, ['ViscoelasticGap', 1, K_KELVIN, 2.0 * xi_a * math.sqrt(K_KELVIN * meff), -1.0e-12],
         'ViscoelasticGap (tension)'),
    ]
    print(f"central impact, m1 = {M1} t, m2 = {M2} t, v0 = {V0} m/s, e = {E}; OpenSees dt = 1e-6 s")
    print("| pound law | realised e (pound) | OpenSees material | realised e (OpenSees) | difference |")
    print("|---|--:|---|--:|--:|")
    for law, k, material, name in rows:
        ep = pound_restitution(exe, law, k)
        eo = opensees_restitution(material)
        print(f"| {law} | {ep:.6f} | {name} | {eo:.6f} | {ep - eo:+.2e} |")


if __name__ == '__main__':
    main()
