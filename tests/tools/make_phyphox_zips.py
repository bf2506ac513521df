#!/usr/bin/python3
"""Writes the zip fixtures of docs/recordings.md ("phyphox's zip export") from
the synthetic phyphox CSVs in data/recordings, with Python's zipfile module:

  data/recordings/phyphox_export.zip     Gyroscope.csv, Accelerometer.csv and
      "Linear Acceleration.csv" (the three phyphox files of data/recordings,
      byte for byte), meta/device.csv and meta/time.csv, deflated;
  tests/bad_recordings/truncated_export.zip   its first half;
  tests/bad_recordings/not_really_a_zip.zip   a zip signature, then text;
  tests/bad_recordings/meta_only.zip          meta/ files and no sensor set;
  tests/bad_recordings/zip_bomb.zip           a 2 GiB uncompressed size stated;
  tests/bad_recordings/two_pendulums.zip      the gyroscope's set beside an
      accelerometer's whose times are stretched by 1.1 (another pendulum's
      run, of period 1.98 s, left in the phone's export).

Usage, from the repository root: /usr/bin/python3 tests/tools/make_phyphox_zips.py
"""
import io
import struct
import zipfile

WHEN = (2026, 1, 1, 12, 0, 0)  # fixed, so that the files do not change from run to run
SETS = [("Gyroscope.csv", "data/recordings/phyphox_gyroscope.csv"),
        ("Accelerometer.csv", "data/recordings/phyphox_acceleration.csv"),
        ("Linear Acceleration.csv", "data/recordings/phyphox_linear_acceleration.csv")]
# phyphox's meta tables; their exact columns do not matter here: meta/ is never a candidate.
META = [("meta/device.csv", '"property","value"\n"deviceModel","synthetic"\n'),
        ("meta/time.csv", '"event","experiment time","system time"\n"START",0.000000000E+00,1.767268800E+09\n')]


def archive(members):
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w") as z:
        for name, data in members:
            info = zipfile.ZipInfo(name, WHEN)
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, data)
    return out.getvalue()


def write(path, data):
    with open(path, "wb") as f:
        f.write(data)


export = archive([(name, open(source, "rb").read()) for name, source in SETS] + META)
write("data/recordings/phyphox_export.zip", export)
write("tests/bad_recordings/truncated_export.zip", export[: len(export) // 2])
write("tests/bad_recordings/not_really_a_zip.zip", b"PK\x03\x04" + b"this is not a zip archive\n" * 4)
write("tests/bad_recordings/meta_only.zip", archive(META))

# A set that states 2 GiB uncompressed, in its local header and in the central
# directory alike (a zip bomb states its true size): refused before unpacking.
bomb = bytearray(archive([("Gyroscope.csv", open(SETS[0][1], "rb").read()[:4000])]))
huge = struct.pack("<I", 2 << 30)
local = bomb.find(b"PK\x03\x04")
bomb[local + 22:local + 26] = huge
central = bomb.find(b"PK\x01\x02")
bomb[central + 24:central + 28] = huge
write("tests/bad_recordings/zip_bomb.zip", bytes(bomb))

# The accelerometer's times stretched by 1.1: the two sets' periods, 1.801 and
# 1.981 s, disagree, and the archive is refused with the --set of each.
lines = open(SETS[1][1]).read().splitlines()
stretched = [lines[0]] + [f"{float(time) * 1.1:.9E},{rest}" for time, rest in (x.split(",", 1) for x in lines[1:])]
write("tests/bad_recordings/two_pendulums.zip",
      archive([(SETS[0][0], open(SETS[0][1], "rb").read()), (SETS[1][0], "\n".join(stretched) + "\n")] + META))
