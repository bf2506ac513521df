#!/usr/bin/python3
"""Tables of settings and periods for tests/tables/ and data/ (docs/series.md, "Tables").

Seeded (numpy's default_rng), so that running it again writes the same files:
    /usr/bin/python3 tests/tools/make_tables.py [FOLDER]
into the repository, or under FOLDER (data/, tests/tables/, tests/bad_recordings/ made there), as the
test that the repository's tables are its output does.
Each table is drawn from the model it is read with: a point bob, T = 2 pi sqrt(L/g) (1 + theta0^2/16)
for a length, T = 2 pi sqrt((k^2 + h^2)/(g h)) (1 + theta0^2/16) for a rigid body (Kelley 1993,
Eqs. 55-56, to the first amplitude term), g = 9.81 m/s^2, each timing's amplitude drawn uniform over
3-15 deg (a hand release whose amplitude nobody wrote down, docs/scene.md), a hand's N(0, 0.06 s) on
each time read off a stopwatch and rounded to 0.01 s; lengths read off a tape to 1 mm.
"""
import math
import os
import sys

import mpmath
import numpy as np

G = 9.81
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def amp_factor(rng, n):
    theta = np.radians(rng.uniform(3.0, 15.0, n))
    return 1.0 + theta**2 / 16.0


def lengths_table(seed, settings_cm, repeats, oscillations=10):
    """Rows (L in cm, time of `oscillations` in s): each setting's length read once, timed `repeats[i]` times."""
    rng = np.random.default_rng(seed)
    rows = []
    for l_cm, n in zip(settings_cm, repeats):
        true_l = l_cm / 100.0 + rng.normal(0.0, 0.001)  # the tape's reading error, once per setting
        t = oscillations * 2 * math.pi * math.sqrt(true_l / G) * amp_factor(rng, n) + rng.normal(0.0, 0.06, n)
        rows += [(l_cm, round(x, 2)) for x in t]
    return rows


def scan_table(seed, h_cm, k=1 / math.sqrt(12), oscillations=10):
    """Rows (h in cm, sigma_h, T in s, sigma_T): a metre stick (k = 1/sqrt(12) m) timed over ten swings at each hole."""
    rng = np.random.default_rng(seed)
    rows = []
    for h in h_cm:
        true_h = h / 100.0 + rng.normal(0.0, 0.0005)
        t10 = oscillations * 2 * math.pi * math.sqrt((k * k + true_h * true_h) / (G * true_h)) * amp_factor(rng, 1)[0]
        t10 = round(t10 + rng.normal(0.0, 0.06), 2)
        rows.append((h, 0.05, round(t10 / oscillations, 4), 0.006))
    return rows


def sweep_table(seed, angles_deg, length, repeats=1, oscillations=1, sigma=0.01):
    """Rows (theta0 in deg as given, time of `oscillations` in s): one pendulum of `length` (m) released at
    each angle, timed `repeats` times, by the exact law T = T0 2K(sin^2(theta0/2))/pi (mpmath's ellipk,
    not pendulum-g's AGM), a hand's N(0, sigma) on each time."""
    rng = np.random.default_rng(seed)
    t0 = 2 * math.pi * math.sqrt(length / G)
    rows = []
    for a in angles_deg:
        law = 2 * float(mpmath.ellipk(math.sin(math.radians(abs(a)) / 2) ** 2)) / math.pi
        rows += [(a, oscillations * t0 * law + x) for x in rng.normal(0.0, sigma, repeats)]
    return rows


def xlsx(sheets):
    """A minimal spreadsheet (.xlsx) as bytes: `sheets` is [(name, rows)], each row a list of cells (None for
    an empty cell, str for a shared string, a number as Excel stores it) written from row 2 (row 1 empty, as
    students leave it)."""
    strings = []

    def cell(ref, v):
        if isinstance(v, str):
            if v not in strings:
                strings.append(v)
            return f'<c r="{ref}" t="s"><v>{strings.index(v)}</v></c>'
        return f'<c r="{ref}"><v>{v!r}</v></c>'

    ns = 'xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main"'
    parts = {}
    for k, (name, rows) in enumerate(sheets, 1):
        body = "".join(f'<row r="{i}">' + "".join(cell(f"{chr(65 + j)}{i}", v) for j, v in enumerate(row) if v is not None)
                       + "</row>" for i, row in enumerate(rows, 2))
        parts[f"xl/worksheets/sheet{k}.xml"] = f'<worksheet {ns}><sheetData>{body}</sheetData></worksheet>'
    parts["xl/sharedStrings.xml"] = f'<sst {ns}>' + "".join(
        f"<si><t>{t.replace('&', '&amp;').replace('<', '&lt;')}</t></si>" for t in strings) + "</sst>"
    return xlsx_parts(parts, [name for name, _ in sheets])


def xlsx_parts(parts, names):
    """The spreadsheet of `parts` (sheets and shared strings, XML as written) with its workbook naming
    the sheets `names` (sheet1.xml, ...), each entry dated 1980-01-01."""
    import io
    import zipfile
    ns = 'xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main"'
    rel = 'xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships"'
    parts = dict(parts)
    parts["xl/workbook.xml"] = f'<workbook {ns} {rel}><sheets>' + "".join(
        f'<sheet name="{name}" sheetId="{k}" r:id="rId{k}"/>' for k, name in enumerate(names, 1)) + "</sheets></workbook>"
    parts["xl/_rels/workbook.xml.rels"] = (
        '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">' + "".join(
            f'<Relationship Id="rId{k}" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/'
            f'worksheet" Target="worksheets/sheet{k}.xml"/>' for k in range(1, len(names) + 1)) + "</Relationships>")
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        for name in ["xl/workbook.xml", "xl/_rels/workbook.xml.rels"] + sorted(
                n for n in parts if n.startswith("xl/") and n not in ("xl/workbook.xml", "xl/_rels/workbook.xml.rels")):
            z.writestr(zipfile.ZipInfo(name, (1980, 1, 1, 0, 0, 0)), parts[name])
    return out.getvalue()


def exact_period(l, theta0_deg):
    """A point bob's period at any amplitude: 4 sqrt(L/g) K(m), m = sin^2(theta0/2) (Kelley 1993, Eq. 17)."""
    m = mpmath.sin(mpmath.radians(theta0_deg) / 2) ** 2
    return float(4 * mpmath.sqrt(mpmath.mpf(l) / G) * mpmath.ellipk(m))


def write(path, text, encoding="utf-8"):
    out = os.path.join(sys.argv[1] if len(sys.argv) > 1 else ROOT, path)
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "wb") as f:
        f.write(text if isinstance(text, bytes) else text.encode(encoding))


def main():
    # data/: 39 rows at 10 lengths (2 to 7 repeats), no amplitude column.
    lengths = [40, 50, 60, 70, 80, 90, 100, 110, 120, 130]
    repeats = [3, 4, 2, 5, 3, 7, 4, 3, 5, 3]
    rows = lengths_table(2026, lengths, repeats)
    write("data/pendulum_lengths_table.csv", "L (cm),t10 (s)\n" + "".join(f"{l:.1f},{t:.2f}\n" for l, t in rows))
    holes = [5, 10, 15, 20, 25, 30, 35, 40, 45]
    scan = scan_table(2027, holes)
    write("data/pivot_scan_table.csv",
          "h (cm),sigma_h (cm),T (s),sigma_T (s)\n" + "".join(f"{h:.1f},{s:.2f},{t:.4f},{u:.3f}\n" for h, s, t, u in scan))

    # tests/tables/: the layouts the reader takes.
    rows = lengths_table(7, [55, 75, 95, 115, 135], [3, 2, 4, 1, 3])
    write("tests/tables/semicolon_decimal_comma_bom.csv",
          "\ufeffLength(cm);10T (s)\n" + "".join(f"{l:.1f};{t:.2f}\n".replace(".", ",") for l, t in rows))
    write("tests/tables/quoted_header.csv",
          '"l (m)","t_{10} (s)"\n' + "".join(f'"{l / 100:.3f}","{t:.2f}"\n' for l, t in rows))
    write("tests/tables/unitless_cm.txt", "L\tt10\n" + "".join(f"{l:.1f}\t{t:.2f}\n" for l, t in rows))
    periods = [(l, round(t / 10, 3), 0.004) for l, t in lengths_table(8, [45, 65, 85, 105, 125], [1] * 5)]
    write("tests/tables/periods_with_sigma.tsv",
          "Length (cm)\tT (s)\t\u03c3T (s)\n" + "".join(f"{l:.1f}\t{t:.3f}\t{u:.3f}\n" for l, t, u in periods))
    # The layouts students type (docs/series.md, "Tables as students type them"): the seed-7 rows as
    # trials beside each other under a units row (times of 10 swings, the count nowhere written), in
    # Dutch with error columns, and headerless in centimetres with the count unwritten.
    trials = {}
    for l, t in rows:
        trials.setdefault(l, []).append(t)
    write("tests/tables/units_row_trials.csv",
          "Length,1st run (second),2nd run (second),3rd run (second),4th run (second)\n(m),,,,\n" +
          "".join(f"{l / 100:.2f}," + ",".join(f"{t:.2f}" for t in ts) + "," * (4 - len(ts)) + "\n"
                  for l, ts in trials.items()))
    write("tests/tables/dutch_errors.csv",
          "lengte (cm), tijd 10 slingeringen (s), fout in lengte (cm), fout in tijd (s)\n" +
          "".join(f"{l:.1f},{t:.2f},0.2,0.06\n" for l, t in rows))
    write("tests/tables/headerless_times_of_swings.txt", "".join(f"{l:.1f}, {t:.2f}\n" for l, t in rows))
    # One timed period per length, no uncertainty: headerless, the periods first (x, y swapped), and
    # L T sigma_L sigma_T with a tab then spaces (a course template's), and matplotlib's names.
    single = [(l, round(t / 10, 3)) for l, t in lengths_table(10, [35, 50, 65, 80, 95, 110], [1] * 6)]
    write("tests/tables/period_first.txt", "\r\n" + "".join(f"{t:.3f}\t{l:.1f}\r\n" for l, t in single))
    write("tests/tables/x_y_sx_sy.txt", "".join(f"{l / 100:.2f}\t{t:.3f} 0.002 0.01\n" for l, t in single))
    write("tests/tables/xerr_yerr.csv",
          "length,period,xerr,yerr\n" + "".join(f"{l / 100:.2f},{t:.3f},0.002,0.01\n" for l, t in single))
    write("tests/tables/l_t_T_g.csv", "L,t,T,g\n" + "".join(
        f"{l:.0f},{10 * t:.2f},{t:.3f},{4 * math.pi**2 * l / 100 / t**2:.3f}\n" for l, t in single))
    write("tests/tables/single_timings.csv", "L (cm),T (s)\n" + "".join(f"{l:.1f},{t:.3f}\n" for l, t in single))
    write("tests/tables/headerless_pivot_scan.txt",
          "".join(f"{h / 100:.3f}, {s / 100:.4f}, {t:.4f}, {u:.3f}\n" for h, s, t, u in scan_table(9, holes)))
    # Amplitude sweeps (docs/series.md, "Amplitude sweeps"): in data/, 0.80 m timed three times at
    # each of 10 to 80 deg; headerless signed radians with their uncertainties (x, y, sigma x, sigma y,
    # a tab then spaces), 0.47 m; a German comment header over times of 5 periods, 1.20 m; headerless
    # degrees after an empty line (CRLF), 0.35 m.
    sweep = sweep_table(11, range(10, 81, 10), 0.80, repeats=3)
    write("data/amplitude_sweep.csv", "theta (deg),T (s)\n" + "".join(f"{a},{t:.3f}\n" for a, t in sweep))
    signed = [a for a in range(80, 0, -10)] + [-a for a in range(10, 81, 10)]
    write("tests/tables/sweep_signed_radians.txt", "".join(
        f"{math.radians(a):.10f}\t{t:.3f} 0.08726646 0.01\n" for a, t in sweep_table(12, signed, 0.47)))
    write("tests/tables/sweep_winkel.txt", "# winkel in grad;t in s     5 Perioden\n" + "".join(
        f"{a};{t:.3f}\n" for a, t in sweep_table(13, range(30, 61, 5), 1.20, oscillations=5, sigma=0.02)) + "\n")
    write("tests/tables/sweep_degrees_headerless.txt", "\r\n" + "".join(
        f"{a}\t{t:.3f}\r\n" for a, t in sweep_table(14, [3.5, 11, 16.5, 20.75, 28.75, 32.5], 0.35, sigma=0.004)))
    # A spreadsheet (docs/series.md, "Tables"): on its first sheet, stamps read off a trace one period
    # apart beside their difference and the length in cm, no unit written, columns C and D empty; on the
    # second, a sweep at 0.351 m written once in the first row, its angle column twice; the third empty.
    stamps = []
    rng = np.random.default_rng(15)
    for l_cm, (_, t) in zip([36.3, 34.7, 31.3, 26.8, 23.4, 17.4], lengths_table(16, [36.3, 34.7, 31.3, 26.8, 23.4, 17.4], [1] * 6, 1)):
        start = round(float(rng.uniform(2.0, 20.0)), 3)
        stamps.append([start, round(start + t, 3), None, None, round(t, 3), l_cm])
    sweep_rows = [[35.1 if i == 0 else None, a, a, round(t, 3)]
                  for i, (a, t) in enumerate(sweep_table(17, [3.5, 11, 16.5, 20.75, 28.75, 32.5], 0.351, sigma=0.004))]
    write("tests/tables/lab_sheet.xlsx", xlsx([
        ("Lengths", [["time1", "time2", None, None, "time", "length"]] + stamps),
        ("Angles", [["length", "angle", "angle", "period"]] + sweep_rows),
        ("Notes", [])]))
    # A spreadsheet as other programs write it: a header's words in runs (spaces kept), a phonetic run
    # beside them (not text), a line break in a cell, a numeric character reference, cells without
    # their reference (each follows the one before), an inline string.
    quirks_rows = "".join(
        f'<row r="{i + 2}"><c><v>{l}</v></c><c><v>{t:.2f}</v></c></row>' for i, (l, t) in enumerate(rows[:6]))
    write("tests/tables/quirks_sheet.xlsx", xlsx_parts({
        "xl/sharedStrings.xml": '<sst xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main">'
                                '<si><r><t xml:space="preserve">Length </t></r><r><t>(cm)</t></r>'
                                '<rPh sb="0" eb="1"><t>XX</t></rPh></si><si><t>t10&#10;(&#x73;)</t></si></sst>',
        "xl/worksheets/sheet1.xml": '<worksheet xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main">'
                                    '<sheetData><row r="1"><c t="s"><v>0</v></c><c t="s"><v>1</v></c>'
                                    '<c t="inlineStr"><is><t>note</t></is></c></row>' + quirks_rows +
                                    '</sheetData></worksheet>'}, ["Sheet1"]))
    # Bad tables (tests/bad_recordings/expected.json).
    write("tests/bad_recordings/table_no_period.csv", "L (cm),theta (deg)\n55,5\n75,5\n")
    write("tests/bad_recordings/table_one_row.csv", "L (cm),t10 (s)\n55,14.9\n")
    write("tests/bad_recordings/table_mixed_units.csv", "L (cm),t10 (s)\n55,14.91\n75,17.38\n0.95,19.55\n115,21.53\n")
    write("tests/bad_recordings/table_text_in_cell.csv", "L (cm),t10 (s)\n55,14.91\n75,17.3B\n95,19.55\n")
    write("tests/bad_recordings/table_setting_not_together.csv",
          "L (cm),t10 (s)\n55,14.91\n75,17.38\n55,14.88\n95,19.55\n")
    write("tests/bad_recordings/table_cell_units_mixed.csv", "10cm,0.68s\n20cm,0.94s\n0.3m,1.17s\n")
    write("tests/bad_recordings/table_degrees_as_radians.csv",
          "theta (rad),T (s)\n10,1.797\n20,1.808\n30,1.825\n40,1.852\n")
    write("tests/bad_recordings/table_amplitude_unit_open.csv",
          "L (cm),t10 (s),theta\n55,14.91,0.5\n75,17.38,0.6\n95,19.55,0.9\n")
    # What reduce refuses in a scene, refused at the cell (issue 42 item 7); periods exact
    # (4 sqrt(L/g) K(sin^2(theta0/2)), point bob), so that only the refused cell is wrong.
    write("tests/bad_recordings/table_timing_sigma_underflow.csv", "L (m),T (s),sigma_T (s)\n" + "".join(
        f"{l},{exact_period(l, 5):.5f},{'1e-200' if l == 0.5 else '0.001'}\n" for l in (0.4, 0.5, 0.6, 0.7)))
    write("tests/bad_recordings/table_length_km.csv",
          "L (m),T (s)\n" + "".join(f"{l:.1e},{exact_period(l, 5):.1f}\n" for l in (1e9, 1.1e9, 1.2e9)))
    write("tests/bad_recordings/table_length_sigma_over_length.csv", "L (cm),sigma_L (cm),T (s)\n" + "".join(
        f"{l},{s},{exact_period(l / 100, 5):.4f}\n" for l, s in ((55, 0.1), (75, 80), (95, 0.1))))
    write("tests/bad_recordings/table_amplitude_180.csv", "L (cm),T (s),theta (deg)\n" + "".join(
        f"{l},{exact_period(l / 100, 5):.4f},{a}\n" for l, a in ((55, 5), (75, 180), (95, 5))))
    write("tests/bad_recordings/table_amplitude_3_2_rad.csv", "L (cm),T (s),theta (rad)\n" + "".join(
        f"{l},{exact_period(l / 100, 5):.4f},{a}\n" for l, a in ((55, 0.1), (75, 3.2), (95, 0.1))))
    # A correct 170 deg row beside 5 deg ones (issue 42 item 8: once refused as mixed units).
    write("tests/tables/amplitude_170.csv", "L (m),T (s),theta (deg)\n" + "".join(
        f"{l},{exact_period(l, a):.5f},{a}\n" for l, a in ((0.5, 5), (0.6, 5), (0.7, 5), (0.8, 170))))


if __name__ == "__main__":
    main()
