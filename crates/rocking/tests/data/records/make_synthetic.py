#!/usr/bin/env python3
"""Writes the synthetic test records of this folder (run once; the files are committed).

Signal: a_k = 0.3 sin(2 pi 2 t_k) exp(-t_k) g, t_k = k dt, dt = 0.01 s, k = 0..199,
rounded to 7 significant digits; the exact zeros of the sine (t = 0, 0.25, ..., 1.75 s)
are written as 0. Every valid file holds these numbers (F10.5 rounds them to 5 decimals,
ESM files hold a_k * 981 cm/s^2 exactly), every malformed one breaks one rule.

    python3 make_synthetic.py      # from this folder
"""

import math
from decimal import Decimal
from pathlib import Path

N, DT = 200, 0.01
HERE = Path(__file__).resolve().parent


def signal():
    """The samples as 7-significant-digit texts (`%.6e`)."""
    out = []
    for k in range(N):
        t = k * DT
        exact_zero = (4 * k) % 100 == 0  # sin(4 pi k / 100) = 0
        a = 0.0 if exact_zero else 0.3 * math.sin(4 * math.pi * t) * math.exp(-t)
        out.append("%.6e" % a)
    return out


def fortran_e(text, width):
    """A `%.6e` text as Fortran Ew.7 writes it: 0.ddddddd mantissa."""
    mantissa, exponent = text.lower().split("e")
    sign = "-" if mantissa.startswith("-") else ""
    digits = mantissa.lstrip("-").replace(".", "")
    power = int(exponent) + 1 if int(digits) else 0
    return ("%s0.%sE%+03d" % (sign, digits, power)).rjust(width)


def e15(text):
    """A value as E15.7 writes it in NGA-West2 files: `  6.3000000E-03`."""
    return "%15.7E" % float(text)


def at2(values, count_line, fmt, per_line, newline="\n", trailing=""):
    """An AT2 file: three title lines, `count_line`, then `per_line` values formatted by `fmt` per line."""
    head = ["SYNTHETIC TEST RECORD, 0.3 sin(4 pi t) exp(-t) g", "rocking test data, not a real earthquake", "ACCELERATION TIME SERIES IN UNITS OF G", count_line]
    rows = ["".join(fmt(v) for v in values[i : i + per_line]) for i in range(0, len(values), per_line)]
    return newline.join(head + rows) + newline + trailing


def esm_header(peak, t_peak, dyna10=False, data_type="ACCELERATION", units="cm/s^2", ndata=True):
    """64 DYNA 1.2 `KEY: value` lines, or the 55 of DYNA 1.0."""
    keys = [
        ("EVENT_NAME", "SYNTHETIC"), ("EVENT_ID", "SYNTH_0001"), ("EVENT_DATE_YYYYMMDD", "20000101"), ("EVENT_TIME_HHMMSS", "000000"),
        ("EVENT_LATITUDE_DEGREE", ""), ("EVENT_LONGITUDE_DEGREE", ""), ("EVENT_DEPTH_KM", ""), ("HYPOCENTER_REFERENCE", ""),
        ("MAGNITUDE_W", ""), ("MAGNITUDE_W_REFERENCE", ""), ("MAGNITUDE_L", ""), ("MAGNITUDE_L_REFERENCE", ""), ("FOCAL_MECHANISM", ""),
        ("NETWORK", "XX"), ("STATION_CODE", "SYN"), ("STATION_NAME", "SYNTHETIC"), ("STATION_LATITUDE_DEGREE", ""),
        ("STATION_LONGITUDE_DEGREE", ""), ("STATION_ELEVATION_M", ""), ("LOCATION", ""), ("SENSOR_DEPTH_M", "0"), ("VS30_M/S", ""),
        ("SITE_CLASSIFICATION_EC8", ""), ("MORPHOLOGIC_CLASSIFICATION", ""), ("EPICENTRAL_DISTANCE_KM", ""),
        ("EARTHQUAKE_BACKAZIMUTH_DEGREE", ""), ("DATE_TIME_FIRST_SAMPLE_YYYYMMDD_HHMMSS", "20000101_000000.000"),
        ("DATE_TIME_FIRST_SAMPLE_PRECISION", "milliseconds"), ("SAMPLING_INTERVAL_S", "0.010000"), ("NDATA", str(N)),
        ("DURATION_S", "%.6f" % ((N - 1) * DT)), ("STREAM", "HNN"), ("UNITS", units), ("INSTRUMENT", ""), ("INSTRUMENT_ANALOG/DIGITAL", "D"),
        ("INSTRUMENTAL_FREQUENCY_HZ", ""), ("INSTRUMENTAL_DAMPING", ""), ("FULL_SCALE_G", ""), ("N_BIT_DIGITAL_CONVERTER", ""),
        ("PGA_CM/S^2", "%.6f" % peak), ("TIME_PGA_S", "%.6f" % t_peak), ("BASELINE_CORRECTION", "BASELINE REMOVED"), ("FILTER_TYPE", ""),
        ("FILTER_ORDER", ""), ("LOW_CUT_FREQUENCY_HZ", ""), ("HIGH_CUT_FREQUENCY_HZ", ""), ("LATE/NORMAL_TRIGGERED", "NT"),
        ("DATABASE_VERSION", ""), ("HEADER_FORMAT", "DYNA 1.0" if dyna10 else "DYNA 1.2"), ("DATA_TYPE", data_type),
        ("PROCESSING", "synthetic, g = 981 cm/s^2"), ("DATA_TIMESTAMP_YYYYMMDD_HHMMSS", ""), ("DATA_LICENSE", "CC0"), ("DATA_CITATION", ""),
        ("DATA_CREATOR", ""), ("ORIGINAL_DATA_MEDIATOR_CITATION", ""), ("ORIGINAL_DATA_MEDIATOR", ""), ("ORIGINAL_DATA_CREATOR_CITATION", ""),
        ("ORIGINAL_DATA_CREATOR", ""), ("USER1", ""), ("USER2", ""), ("USER3", ""), ("USER4", ""), ("USER5", ""),
    ]
    only_12 = {"SENSOR_DEPTH_M", "DATA_LICENSE", "DATA_CITATION", "DATA_CREATOR", "ORIGINAL_DATA_MEDIATOR_CITATION", "ORIGINAL_DATA_MEDIATOR",
               "ORIGINAL_DATA_CREATOR_CITATION", "ORIGINAL_DATA_CREATOR", "USER5"}
    keys = [(k, v) for k, v in keys if not (dyna10 and k in only_12) and (ndata or k != "NDATA")]
    assert len(keys) == (55 if dyna10 else 64) - (0 if ndata else 1)
    return "".join(("%s: %s" % (k, v)).rstrip() + "\n" for k, v in keys)


def write(name, text):
    """Writes a file of this folder, line endings as given."""
    (HERE / name).write_bytes(text.encode("ascii"))


def main():
    values = signal()
    gal = [Decimal(v) * 981 for v in values]  # exact: 7 digits times 3
    assert all(Decimal("%.9E" % a) == a for a in gal)  # 10 significant digits keep it exact
    k_peak = max(range(N), key=lambda k: abs(float(values[k])))
    peak, t_peak = float(values[k_peak]), k_peak * DT
    f10 = ["%10.5f" % float(v) for v in values]
    assert max(range(N), key=lambda k: abs(float(f10[k]))) == k_peak

    keyed = "NPTS=   %d, DT=   .0100 SEC," % N
    write("synthetic.csv", "time,acceleration\n" + "".join("%.2f,%s\n" % (k * DT, v) for k, v in enumerate(values)))
    write("synthetic_dt.csv", "".join(v + "\n" for v in values))
    write("synthetic_dexp.csv", "time,acceleration\n" + "".join("%s,%s\n" % (("%.2E" % (k * DT)).replace("E", "D"), v.replace("e", "D")) for k, v in enumerate(values)))
    write("synthetic.AT2", at2(values, keyed, e15, 5))
    write("synthetic_f10.AT2", at2(values, "   %d    0.0100    NPTS, DT" % N, lambda v: "%10.5f" % float(v), 8))
    write("synthetic_crlf.AT2", at2(values, "NPTS=   %d, DT=   .0100 SEC" % N, e15, 5, newline="\r\n", trailing="\r\n"))
    write("synthetic_runtogether.AT2", at2(values, keyed, lambda v: fortran_e(v, 14), 5))
    write("synthetic.ASC", esm_header(peak * 981, t_peak) + "".join("%.9E\n" % a for a in gal))
    write("synthetic_dyna10.ASC", esm_header(peak * 981, t_peak, dyna10=True) + "".join("%s\n" % format(a, "f") for a in gal))

    write("short.AT2", at2(values[:-1], keyed, e15, 5))
    write("long.AT2", at2(values + [values[0]], keyed, e15, 5))
    write("zero_dt.AT2", at2(values, "NPTS=   %d, DT=   .0000 SEC," % N, e15, 5))
    lines = at2(values, keyed, e15, 5).split("\n")
    bad = lines[9][15:30].replace("E-0", "E-O")  # line 10, third value: letter O for a zero
    lines[9] = lines[9][:15] + bad + lines[9][30:]
    write("nonnumeric.AT2", "\n".join(lines))
    write("missing_ndata.ASC", esm_header(peak * 981, t_peak, ndata=False) + "".join("%.9E\n" % a for a in gal))
    write("velocity.ASC", esm_header(peak * 981, t_peak, data_type="VELOCITY", units="cm/s") + "".join("%.9E\n" % a for a in gal))

    print("peak %s g = %s cm/s^2 at t = %.2f s (sample %d); nonnumeric.AT2 line 10: %r" % (values[k_peak], gal[k_peak], t_peak, k_peak, bad.strip()))


if __name__ == "__main__":
    main()
