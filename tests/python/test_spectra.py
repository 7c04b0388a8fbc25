"""Records and response spectra from Python (polydem.analytical.read_record,
record_suite, response_spectrum, spectra) against `polydem analytic
spectrum`'s CSV and against the record files themselves."""
import csv
import math

import numpy as np
import polydem
import pytest
from conftest import deck, polydem_cli

SYNTHETIC = deck("examples/spire/synthetic_record.csv")
G = 9.80665


def test_read_record_converts_g_and_scales_time():
    t, a = polydem.analytical.read_record(SYNTHETIC)
    rows = np.loadtxt(SYNTHETIC, delimiter=",", skiprows=1)
    assert np.array_equal(t, rows[:, 0])
    assert np.allclose(a, rows[:, 1] * G, rtol=1e-15, atol=0)
    t4, a4 = polydem.analytical.read_record(SYNTHETIC, scale=2.0, length_scale=0.25)
    assert np.allclose(t4, 0.5 * t)
    assert np.allclose(a4, 2 * a)


def test_spectra_match_the_command_line(tmp_path):
    periods = [0.05, 0.147, 0.5, 1.0]
    p = polydem_cli("analytic", "spectrum", SYNTHETIC, "--periods", ",".join(map(str, periods)),
                    "--out", str(tmp_path / "out"), "--no-plot")
    assert p.returncode == 0, p.stderr
    with open(tmp_path / "out" / "spectra.csv") as f:
        rows = list(csv.DictReader(f))
    s = polydem.analytical.spectra([SYNTHETIC], periods=periods)
    assert s["names"] == ["synthetic_record"]
    r = s["spectra"][0]
    for j, row in enumerate(rows):
        assert float(row["synthetic_record.psa_g"]) == pytest.approx(r["psa"][j] / G, rel=1e-8)
        assert float(row["synthetic_record.sd_m"]) == pytest.approx(r["sd"][j], rel=1e-8)
        assert r["psa"][j] == pytest.approx((2 * math.pi / periods[j]) ** 2 * r["sd"][j], rel=1e-14)


def test_suite_median_and_dispersion(tmp_path):
    (tmp_path / "suite.toml").write_text(
        f'[suite]\nname = "two"\n[[record]]\nfile = "{SYNTHETIC}"\n'
        f'[[record]]\nname = "double"\nfile = "{SYNTHETIC}"\nscale = 2.0\n')
    suite = polydem.analytical.record_suite(str(tmp_path / "suite.toml"))
    assert [r["name"] for r in suite["records"]] == ["synthetic_record", "double"]
    assert suite["records"][1]["components"][0]["scale"] == 2.0
    s = polydem.analytical.spectra(suite=str(tmp_path / "suite.toml"), periods=[0.2, 0.4])
    assert np.allclose(s["median_psa"], math.sqrt(2) * s["spectra"][0]["psa"], rtol=1e-12)
    assert np.allclose(s["dispersion"], math.log(2) / math.sqrt(2), rtol=1e-12)


def test_response_spectrum_of_arrays():
    t = np.linspace(0.0, 2.0, 201)
    a = np.sin(2 * math.pi * 2.0 * t)
    r = polydem.analytical.response_spectrum(t, a, periods=[1e-4])
    assert r["psa"][0] == pytest.approx(r["pga"], rel=1e-3)
    assert len(polydem.analytical.response_spectrum(t, a)["period"]) == 100


def test_bad_input_raises_deck_error_with_file_and_line(tmp_path):
    bad = tmp_path / "no_unit.csv"
    bad.write_text("0,0\n0.01,0.1\n")
    with pytest.raises(polydem.errors.DeckError, match="no_unit.csv:1: no acceleration unit declared"):
        polydem.analytical.read_record(str(bad))
    (tmp_path / "suite.toml").write_text(f'[[record]]\nfile = "{SYNTHETIC}"\nscale = -1\n')
    with pytest.raises(polydem.errors.DeckError) as e:
        polydem.analytical.spectra(suite=str(tmp_path / "suite.toml"))
    assert e.value.line == 3 and e.value.key == "record[1].scale"
    with pytest.raises(polydem.errors.DeckError, match="period must be > 0"):
        polydem.analytical.spectra([SYNTHETIC], periods=[0.0])
