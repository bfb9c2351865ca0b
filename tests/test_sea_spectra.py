"""Spectra and spreading (REFERENCES §1-2): Hs, peak, depth limits, normalisation."""

import math

import numpy as np
import pytest
from scipy import integrate, special

from marinesim.constants import G
from marinesim.errors import ParameterError
from marinesim.sea import (Cos2s, HalfPlaneCos2n, Jonswap, JonswapFetch, Mitsuyasu,
                           PiersonMoskowitz, Tma)
from marinesim.sea.spectra import dnv_gamma, kitaigorodskii_factor

OMEGA = np.linspace(1e-3, 12.0, 600_001)  # an independent trapezoid grid, not the code's quadrature


def trapezoid_m0(spectrum) -> float:
    return float(np.trapezoid(spectrum.density(OMEGA), OMEGA))


SPECTRA = [
    PiersonMoskowitz(2.5, 8.0),
    Jonswap(4.0, 10.0, 1.0),
    Jonswap(4.0, 10.0, 3.3),
    Jonswap(6.0, 11.0, 7.0),
    Jonswap(3.0, 6.5),  # DNV default gamma (Tp/sqrt(Hs) = 3.75)
    Tma(3.0, 9.0, 3.3, depth=20.0),
    Tma(2.0, 12.0, 2.0, depth=8.0),
]


@pytest.mark.parametrize("spectrum", SPECTRA, ids=repr)
def test_hs_is_four_sqrt_m0(spectrum):
    # a spectrum whose variance is off by 2% has Hs off by 1%
    assert 4.0 * math.sqrt(trapezoid_m0(spectrum)) == pytest.approx(spectrum.hs, rel=0.01)


@pytest.mark.parametrize("spectrum", [s for s in SPECTRA if not isinstance(s, Tma)], ids=repr)
def test_peak_at_tp(spectrum):
    density = spectrum.density(OMEGA)
    peak_period = 2 * math.pi / OMEGA[np.argmax(density)]
    assert peak_period == pytest.approx(spectrum.tp, rel=1e-3)


def test_pierson_moskowitz_is_jonswap_with_gamma_one():
    omega = np.linspace(0.2, 3.0, 100)
    np.testing.assert_allclose(Jonswap(3.0, 9.0, 1.0).density(omega), PiersonMoskowitz(3.0, 9.0).density(omega),
                               rtol=1e-8)


def test_jonswap_peak_enhancement_ratio():
    # at the peak, S_J / S_PM = A_norm * gamma: with gamma 3.3 the peak is ~2.5x the PM peak (same Hs)
    wp = 2 * math.pi / 10.0
    ratio = Jonswap(4.0, 10.0, 3.3).density(np.array([wp]))[0] / PiersonMoskowitz(4.0, 10.0).density(np.array([wp]))[0]
    assert ratio == pytest.approx(3.3 * (1 - 0.287 * math.log(3.3)), rel=0.03)  # DNV's A_g within 3%


def test_dnv_default_gamma():
    assert dnv_gamma(4.0, 7.0) == 5.0  # Tp/sqrt(Hs) = 3.5
    assert dnv_gamma(1.0, 6.0) == 1.0  # ratio 6
    assert dnv_gamma(4.0, 8.4) == pytest.approx(math.exp(5.75 - 1.15 * 4.2))
    assert Jonswap(4.0, 7.0).gamma == 5.0


def test_tma_tends_to_jonswap_in_deep_water():
    omega = np.linspace(0.3, 3.0, 200)
    deep = Jonswap(3.0, 9.0, 3.3).density(omega)
    for depth, tol in [(20.0, None), (200.0, 1e-3), (2000.0, 1e-9)]:
        tma = Tma(3.0, 9.0, 3.3, depth=depth).density(omega)
        if tol is None:  # shallow: clearly different, the low frequencies are cut
            assert np.max(np.abs(tma - deep)) > 0.05 * deep.max()
        else:
            np.testing.assert_allclose(tma, deep, atol=tol * deep.max())


def test_kitaigorodskii_factor_limits_and_thompson_vincent():
    h = 10.0
    omega = np.linspace(0.01, 4.0, 400)
    phi = kitaigorodskii_factor(omega, h)
    wh = omega * math.sqrt(h / G)
    approx = np.where(wh <= 1, 0.5 * wh**2, np.where(wh < 2, 1 - 0.5 * (2 - wh) ** 2, 1.0))
    # Thompson-Vincent is an approximation of the exact factor to within a few hundredths
    assert np.max(np.abs(phi - approx)) < 0.04
    assert phi[0] == pytest.approx(0.5 * wh[0] ** 2, rel=1e-3)  # shallow limit
    assert phi[-1] == pytest.approx(1.0, abs=1e-6)              # deep limit


def test_jonswap_from_wind_and_fetch():
    # Hasselmann 1973: f_p = 3.5 (g/U) X^(-1/3), X = g F / U^2 (without the ^(1/3): off x20)
    u10, fetch = 15.0, 200e3
    spectrum = JonswapFetch(u10, fetch)
    x = G * fetch / u10**2
    assert 1.0 / spectrum.tp == pytest.approx(3.5 * G / u10 * x ** (-1 / 3), rel=2e-3)
    # far above the peak S -> alpha g^2 w^-5 exp(-5/4 (wp/w)^4), alpha = 0.076 X^-0.22 (Phillips level)
    w = 4.0 * 2 * math.pi / spectrum.tp
    tail = spectrum.density(np.array([w]))[0] * w**5 / G**2 / math.exp(-1.25 / 4**4)
    assert tail == pytest.approx(0.076 * x**-0.22, rel=1e-6)
    assert 4.0 * math.sqrt(trapezoid_m0(spectrum)) == pytest.approx(spectrum.hs, rel=0.01)


SPREADINGS = [Cos2s(1.0), Cos2s(15.0), Cos2s(75.0), Cos2s(2.5), HalfPlaneCos2n(1), HalfPlaneCos2n(10),
              Mitsuyasu(10.0, 0.6)]


@pytest.mark.parametrize("spreading", SPREADINGS, ids=repr)
@pytest.mark.parametrize("omega", [0.3, 0.6, 1.5])
def test_spreading_integrates_to_one(spreading, omega):
    value, _ = integrate.quad(lambda t: spreading.density(np.array([t]), np.array([omega]))[0], -math.pi, math.pi,
                              points=[0.0], limit=400)
    assert value == pytest.approx(1.0, rel=1e-6)


@pytest.mark.parametrize("spreading", SPREADINGS, ids=repr)
def test_mean_resultant_length(spreading):
    omega = 0.9
    value, _ = integrate.quad(lambda t: math.cos(t) * spreading.density(np.array([t]), np.array([omega]))[0],
                              -math.pi, math.pi, points=[0.0], limit=400)
    assert spreading.mean_resultant_length(np.array([omega]))[0] == pytest.approx(value, rel=1e-6)


def test_cos2s_normalisation_second_form():
    # C(s) = 2^(2s-1)/pi Gamma(s+1)^2/Gamma(2s+1)  (REFERENCES §2)
    for s in [1.0, 4.0, 15.0, 40.0]:
        other = 2 ** (2 * s - 1) / math.pi * special.gamma(s + 1) ** 2 / special.gamma(2 * s + 1)
        assert Cos2s(s).density(np.array([0.0]), np.array([1.0]))[0] == pytest.approx(other, rel=1e-10)


def test_mitsuyasu_s_varies_with_frequency():
    m = Mitsuyasu(20.0, 0.5)
    assert m.s(np.array([0.5]))[0] == pytest.approx(20.0)
    assert m.s(np.array([0.25]))[0] == pytest.approx(20.0 / 32.0)          # (1/2)^5
    assert m.s(np.array([1.0]))[0] == pytest.approx(20.0 * 2**-2.5)        # 2^-2.5


@pytest.mark.parametrize("make, value", [
    (lambda: Jonswap(-1.0, 10.0), "-1.0"),
    (lambda: Jonswap(0.0, 10.0), "0.0"),
    (lambda: Jonswap(4.0, -3.0), "-3.0"),
    (lambda: Jonswap(4.0, 10.0, 0.5), "0.5"),
    (lambda: Jonswap(float("nan"), 10.0), "nan"),
    (lambda: Jonswap(4.0, float("nan")), "nan"),
    (lambda: Tma(4.0, 10.0, 3.3, depth=-5.0), "-5.0"),
    (lambda: Tma(4.0, 10.0, 3.3, depth=0.0), "0.0"),
    (lambda: PiersonMoskowitz(4.0, 0.0), "0.0"),
    (lambda: JonswapFetch(-10.0, 1e5), "-10.0"),
    (lambda: Cos2s(-2.0), "-2.0"),
])
def test_bad_parameters_raise_project_error_naming_the_value(make, value):
    with pytest.raises(ParameterError, match=value.replace(".", r"\.")):
        make()
