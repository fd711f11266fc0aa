# Combines the runs (minimum CPU time per point), interpolates RK4's time at each point's
# error (log-log, piecewise linear between RK4's step counts, extrapolated along the end
# segments) and prints the note's table.
import math, sys, glob
rows = {}
for f in sorted(glob.glob('/tmp/gslode/run*.txt')):
    for l in open(f):
        if l.startswith('#') or l.startswith('method'): continue
        w = l.split()
        key = (w[0], w[1])
        r = dict(method=w[0], param=w[1], steps=float(w[2]), rhs=float(w[3]), te=float(w[6]), fe=float(w[7]), ms=float(w[8]))
        if key in rows: rows[key]['ms'] = min(rows[key]['ms'], r['ms'])
        else: rows[key] = r
def line(name):
    pts = sorted([r for r in rows.values() if r['method'] == name], key=lambda r: -r['te'])
    return pts
def interp(pts, err, which):
    xs = [(math.log(p[which]), math.log(p['ms'])) for p in pts if p[which] > 0]
    xs.sort(reverse=True)  # decreasing error
    le = math.log(err)
    for i in range(len(xs) - 1):
        (e0, t0), (e1, t1) = xs[i], xs[i + 1]
        if e1 <= le <= e0 or (i == 0 and le > e0) or (i == len(xs) - 2 and le < e1):
            return math.exp(t0 + (le - e0) * (t1 - t0) / (e1 - e0))
rk4 = [r for r in line('RK4(ref/ode)') if r['param'] in ('2048', '2896', '4096', '8192', '16384')]
rk4p = line('RK4(prodRHS)')
order = ['RK4(ref/ode)', 'RK4(prodRHS)', 'rk8pd(fixed)', 'rk8pd', 'rk8pd/loop', 'rkck', 'rkf45', 'msadams']
print('| method | tol / steps a cycle | steps/cycle | RHS evals/cycle | TE error | force error | CPU ms | RK4 ms at equal TE error | ratio (TE) | ratio (force) | ratio vs RK4 on the production RHS (TE) |')
print('|---|---|---|---|---|---|---|---|---|---|---|')
for m in order:
    for r in line(m):
        if r['te'] > 1e-3 or (m == 'rk8pd(fixed)' and r['param'] == '96') or (m == 'rk8pd/loop' and r['param'] not in ('1e-6', '1e-7')): continue
        t_te = interp(rk4, r['te'], 'te'); t_fe = interp(rk4, r['fe'], 'fe'); t_p = interp(rk4p, r['te'], 'te')
        rk = m.startswith('RK4')
        print(f"| {m} | {r['param']} | {r['steps']:.0f} | {r['rhs']:.0f} | {r['te']:.1e} | {r['fe']:.1e} | {r['ms']:.1f} | "
              + ('—' if rk else f"{t_te:.0f}") + ' | ' + ('—' if rk else f"{t_te/r['ms']:.2f}") + ' | '
              + ('—' if rk else f"{t_fe/r['ms']:.2f}") + ' | ' + ('—' if rk else f"{t_p/r['ms']:.2f}") + ' |')
print()
print('At exactly TE error 1e-6 and 1e-7 (each line interpolated log-log along its own sweep):')
for target in (1e-6, 1e-7, 1e-8):
    t4 = interp(rk4, target, 'te'); t4p = interp(rk4p, target, 'te')
    out = [f"RK4 {t4:.0f} ms (same RHS {t4p:.0f})"]
    for m in ('rk8pd(fixed)', 'rk8pd', 'rk8pd/loop', 'rkck/loop', 'rkf45'):
        pts = [r for r in line(m) if r['te'] < 1e-3 and (m != 'rk8pd(fixed)' or r['param'] != '96')]
        t = interp(pts, target, 'te')
        out.append(f"{m} {t:.1f} ms = {t4/t:.2f}x (same RHS {t4p/t:.2f}x)")
    print(f"- {target:.0e}: " + '; '.join(out))
