#!/usr/bin/env bash
# hullopt coefficients end to end: coefficients.csv with units in the header, the coefficients reproduce
# rao.csv of `hullopt rao` on the same config through the 2x2 equations of motion (solved here, in Python),
# measured points drawn from compare:, and one-line errors for coefficients asked of the time-marching path
# and for frequencies the strip kernel does not resolve.
set -u
bin="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

base() {  # $1: extra solver keys, $2: frequencies block
  cat <<YAML
hull: { offsets_csv: $PWD/data/delft372/delft372_offsets.csv, draught_m: 0.15, length_m: 3.0, hulls: 2, spacing_m: 0.70 }
mass: { mass_kg: 87.07, lcg_m_from_ap: 1.41, kyy_m: 0.782 }
speed: { Fn: 0.75 }
water: { rho_kg_m3: 1000 }
solver: { sections: 20, panels: 8, Cs: 0.024, $1 frequencies: $2 }
YAML
}

base "" "{ lambda_over_L: [1.2, 1.5, 1.8, 2.1, 2.5] }" > "$tmp/ok.yaml"
cp "$tmp/ok.yaml" "$tmp/cmp.yaml"
cat >> "$tmp/cmp.yaml" <<YAML
compare:
  forced_heave_csv: $PWD/data/delft372/delft372_forced_heave_coefficients.csv
  forced_pitch_csv: $PWD/data/delft372/delft372_forced_pitch_coefficients.csv
  wave_loads_csv: $PWD/data/delft372/delft372_restrained_wave_loads.csv
YAML
"$bin" coefficients "$tmp/cmp.yaml" --out "$tmp/c" > "$tmp/c.out" || fail "good config refused"
grep -q "measured points drawn: 9 heave, 9 pitch, 9 wave loads" "$tmp/c.out" || fail "measured points: $(cat "$tmp/c.out")"
[ -s "$tmp/c/coefficients.svg" ] || fail "no coefficients.svg"
header=$(awk '!/^#/ { print; exit }' "$tmp/c/coefficients.csv")
case "$header" in
  omega_e_rad_s,omega_rad_s,lambda_over_L,omega_e_sqrt_L_over_g,A33_kg,B33_kg_per_s,A35_kg_m,*F5_Cs_phase_deg) ;;
  *) fail "coefficients.csv header: $header" ;;
esac
grep -qi nan "$tmp/c/coefficients.csv" && fail "NaN in coefficients.csv"
reproduces() {  # $1: coefficients.csv, $2: rao.csv of the same config
/usr/bin/python3 - "$1" "$2" <<'PY'
import csv, math, re, sys
def rows(p):
    lines = [l for l in open(p) if not l.startswith('#')]
    return list(csv.DictReader(lines))
head = open(sys.argv[1]).read()
M = float(re.search(r'mass = ([0-9.eE+-]+) kg', head).group(1))
I = float(re.search(r'pitch inertia = ([0-9.eE+-]+) kg', head).group(1))
g = float(re.search(r'g = ([0-9.eE+-]+) m/s\^2', head).group(1))
tol = 1e-6  # both files carry 10 significant digits
for c, r in zip(rows(sys.argv[1]), rows(sys.argv[2])):
    w = float(c['omega_e_rad_s']); k = float(c['omega_rad_s'])**2 / g
    f = lambda n: float(c[n])
    def m(i, j, mass):
        return -w*w*(mass + f(f'A{i}{j}_kg' + ('' if (i, j) == (3, 3) else '_m' if i != j else '_m2'))) \
               + 1j*w*f(f'B{i}{j}_kg' + ('_per_s' if (i, j) == (3, 3) else '_m_per_s' if i != j else '_m2_per_s'))
    C = {(3,3): f('C33_N_per_m'), (3,5): f('C35_N_per_rad'), (5,3): f('C53_N'), (5,5): f('C55_N_m_per_rad')}
    a11 = m(3,3,M) + C[3,3]; a12 = m(3,5,0) + C[3,5]; a21 = m(5,3,0) + C[5,3]; a22 = m(5,5,I) + C[5,5]
    F3 = f('F3_amp_N_per_m') * complex(math.cos(math.radians(f('F3_phase_deg'))), math.sin(math.radians(f('F3_phase_deg'))))
    F5 = f('F5_amp_N_m_per_m') * complex(math.cos(math.radians(f('F5_phase_deg'))), math.sin(math.radians(f('F5_phase_deg'))))
    det = a11*a22 - a12*a21
    x3 = (a22*F3 - a12*F5)/det; x5 = (a11*F5 - a21*F3)/det/k
    for x, amp, ph in ((x3, 'heave_amp', 'heave_phase_deg'), (x5, 'pitch_amp', 'pitch_phase_deg')):
        ref = float(r[amp]) * complex(math.cos(math.radians(float(r[ph]))), math.sin(math.radians(float(r[ph]))))
        if abs(x - ref) > tol * abs(ref):
            sys.exit(f"omega_e {w}: {amp} {abs(x)} vs rao.csv {abs(ref)}")
PY
}
"$bin" rao "$tmp/ok.yaml" --out "$tmp/r" > /dev/null || fail "rao refused the same config"
reproduces "$tmp/c/coefficients.csv" "$tmp/r/rao.csv" || fail "coefficients do not reproduce rao.csv"
# At a running attitude the coefficients are those of the trimmed hull, as the RAOs are.
sed 's/spacing_m: 0.70 }/spacing_m: 0.70, attitude: { sinkage_m: -0.00257, trim_deg: 1.35 } }/' "$tmp/ok.yaml" > "$tmp/att.yaml"
grep -q attitude "$tmp/att.yaml" || fail "test set-up: no attitude in att.yaml"
"$bin" coefficients "$tmp/att.yaml" --out "$tmp/ca" > /dev/null || fail "attitude config refused"
"$bin" rao "$tmp/att.yaml" --out "$tmp/ra" > /dev/null || fail "rao refused the attitude config"
reproduces "$tmp/ca/coefficients.csv" "$tmp/ra/rao.csv" || fail "coefficients at the attitude do not reproduce its rao.csv"
/usr/bin/python3 - "$tmp/ok.yaml" "$tmp/c/coefficients.csv" "$tmp/ca/coefficients.csv" <<'PY' || fail "the attitude does not change the coefficients"
import csv, sys
rows = lambda p: list(csv.DictReader(l for l in open(p) if not l.startswith('#')))
b0 = [float(r['B33_kg_per_s']) for r in rows(sys.argv[2])]
b1 = [float(r['B33_kg_per_s']) for r in rows(sys.argv[3])]
# 1.35 deg of trim on a 0.15 m draught moves the transom 35 mm down: B33 changes by far more than 1 %.
sys.exit(0 if all(abs(a - b) > 0.01 * abs(a) for a, b in zip(b0, b1)) else f"B33 {b0} vs {b1}")
PY

expect_error() {  # $1: name, $2: config text, $3: text the message must contain
  echo "$2" > "$tmp/$1.yaml"
  if "$bin" coefficients "$tmp/$1.yaml" --out "$tmp/$1" 2> "$tmp/$1.err"; then fail "$1: accepted"; fi
  grep -q "hullopt: error:" "$tmp/$1.err" || fail "$1: not a clean error: $(cat "$tmp/$1.err")"
  grep -q "$3" "$tmp/$1.err" || fail "$1: message lacks '$3': $(cat "$tmp/$1.err")"
  [ "$(wc -l < "$tmp/$1.err")" = 1 ] || fail "$1: error is not one line"
}
expect_error time_marching "$(base "path: time_marching," "{ lambda_over_L: [1.5] }")" "path: time_marching"
# 20 sections at Fn 0.75: dt = 0.0368 s, so omega_e above 21.3 rad/s is not resolved (lambda/L 0.3: 29 rad/s).
expect_error unresolved "$(base "" "{ lambda_over_L: [0.3, 1.5] }")" "outside the strip kernel's range"
expect_error no_frequencies "$(cat <<YAML
hull: { offsets_csv: $PWD/data/delft372/delft372_offsets.csv, draught_m: 0.15, length_m: 3.0, hulls: 2, spacing_m: 0.70 }
speed: { Fn: 0.75 }
water: { rho_kg_m3: 1000 }
solver: { sections: 20, panels: 8 }
YAML
)" "frequencies"
expect_error bad_compare "$(base "" "{ lambda_over_L: [1.5] }")
compare: { forced_heave_csv: nowhere.csv }" "nowhere.csv"
echo "coefficients CLI: ok"
