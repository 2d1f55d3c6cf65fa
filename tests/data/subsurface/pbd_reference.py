#!/usr/bin/python3
"""Independent numerical evaluation of the photon beam diffusion (PBD) BSSRDF profile for
tests/materials/subsurface_test.cpp: the same published formulas (Habel, Christensen, Jarosz,
"Photon Beam Diffusion: A Hybrid Monte Carlo Method for Subsurface Scattering", EGSR 2013,
eqs. for the single-scattering and multiple-scattering beam integrals, with Grosjean's diffusion
coefficient and d'Eon's extrapolated boundary; pbrt-v4 book section 11.5), computed here in
double precision with fine quadrature (2e5-point midpoint rule in the exponential's CDF; 2e4 inside the albedo integrals) and
Fresnel moments integrated numerically instead of pbrt-v4's polynomial fits. The C++ code
uses 100 stratified depth samples and the fits, so the two agree to the quadrature error, not
bit for bit.

Writes pbd_reference.txt:
  profile sigma_s sigma_a g eta r S_ss S_ms
  rho_eff g eta rho value     (integral of 2 pi r (S_ss + S_ms) over r in [0, r_max] at sigma_t 1,
                               r_max the table's last radius 2.5e-3 * 1.2^62, 600 log-spaced radii, trapezoid)
Run: /usr/bin/python3 pbd_reference.py > pbd_reference.txt
"""
import numpy as np

N = 200000
U = (np.arange(N) + 0.5) / N
# The albedo integrals evaluate the profile at 600 radii: 2e4 depth samples each suffice there.
U_COARSE = (np.arange(20000) + 0.5) / 20000


def fresnel(c, eta):
    c = np.clip(c, -1.0, 1.0)
    eta = np.where(c < 0, 1.0 / eta, eta)
    c = np.abs(c)
    s2 = (1 - c * c) / eta**2
    ct = np.sqrt(np.maximum(0.0, 1 - s2))
    rpa = (eta * c - ct) / (eta * c + ct)
    rpe = (c - eta * ct) / (c + eta * ct)
    return np.where(s2 >= 1, 1.0, 0.5 * (rpa**2 + rpe**2))


def moment(eta, i):
    # pbrt-v4's FresnelMoment_i(eta): int_0^1 Fr(mu) mu^i dmu for light arriving from the side of
    # relative index eta (its fits match this reading: FresnelMoment1(1.33) ~ 0.236).
    return np.mean(fresnel(-U, eta) * U**i)


def hg(cos_theta, g):  # pbrt-v4's convention: both directions pointing away
    g = np.clip(g, -0.99, 0.99)
    d = 1 + g * g + 2 * g * cos_theta
    return (1 - g * g) / (4 * np.pi * d * np.sqrt(d))


def s_ms(ss, sa, g, eta, r, U=U):
    sps = ss * (1 - g)
    spt = sa + sps
    rhop = sps / spt
    D = (2 * sa + sps) / (3 * spt * spt)
    str_ = np.sqrt(sa / D)
    fm1, fm2 = moment(eta, 1), moment(eta, 2)
    ze = -2 * D * (1 + 3 * fm2) / (1 - 2 * fm1)
    cphi, ce = 0.25 * (1 - 2 * fm1), 0.5 * (1 - 3 * fm2)
    zr = -np.log(1 - U) / spt
    zv = -zr + 2 * ze
    dr, dv = np.sqrt(r * r + zr * zr), np.sqrt(r * r + zv * zv)
    phi = 1 / (4 * np.pi) / D * (np.exp(-str_ * dr) / dr - np.exp(-str_ * dv) / dv)
    edn = 1 / (4 * np.pi) * (zr * (1 + str_ * dr) * np.exp(-str_ * dr) / dr**3 -
                             zv * (1 + str_ * dv) * np.exp(-str_ * dv) / dv**3)
    kappa = 1 - np.exp(-2 * spt * (dr + zr))
    return np.mean(kappa * rhop * rhop * (phi * cphi + edn * ce))


def s_ss(ss, sa, g, eta, r, U=U):
    st = ss + sa
    rho = ss / st
    tc = r * np.sqrt(max(eta * eta - 1, 0.0))
    t = tc - np.log(1 - U) / st
    d = np.sqrt(r * r + t * t)
    c = t / d
    return np.mean(rho * np.exp(-st * (d + tc)) / d**2 * hg(c, g) * (1 - fresnel(-c, eta)) * np.abs(c))


def rho_eff(rho, g, eta):
    rmax = 2.5e-3 * 1.2**62
    r = np.concatenate([[0.0], np.geomspace(1e-5, rmax, 600)])
    f = np.array([0.0] + [2 * np.pi * x * (s_ss(rho, 1 - rho, g, eta, x, U_COARSE) + s_ms(rho, 1 - rho, g, eta, x, U_COARSE))
                          for x in r[1:]])
    return np.trapz(f, r)


for ss, sa, g, eta in [(0.9, 0.1, 0.0, 1.33), (0.5, 0.5, 0.0, 1.5), (2.0, 0.05, 0.5, 1.33), (0.99, 0.01, -0.3, 1.2)]:
    for r in [0.05, 0.2, 0.5, 1.0, 2.0, 5.0]:
        print(f"profile {ss} {sa} {g} {eta} {r} {s_ss(ss, sa, g, eta, r):.9e} {s_ms(ss, sa, g, eta, r):.9e}")
for g, eta in [(0.0, 1.33), (0.5, 1.5)]:
    for i in [20, 50, 80, 99]:  # the table's albedo nodes (100 of them)
        rho = (1 - np.exp(-8 * i / 99)) / (1 - np.exp(-8))
        print(f"rho_eff {g} {eta} {i} {rho_eff(rho, g, eta):.9e}")
