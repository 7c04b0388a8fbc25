#!/usr/bin/env python3
"""Stable steps of central differences with stiffness-proportional joint
damping, explicit and with each block's own dashpots taken implicitly.

Issue 12 weighs "the damping term without the step penalty". This script
measures, on random spring-dashpot networks (1 to 8 masses over three
decades, springs between them and to the ground, C = beta*K with the damping
ratio xi at the highest frequency), the largest omega*dt at which each scheme
is stable (spectral radius of the step's amplification matrix <= 1):

  explicit    M*dv = dt*(-K*x - C*v)                    (polydem today)
  block       (M + dt*D)*dv = dt*(-K*x - C*v)           D = block diagonal of C
  predicted   (M + dt*D)*dv = dt*(-K*x - C*(v + theta*dv_prev) + D*dv_prev)

(v at the half step before, dv the step's velocity change). docs/benchmarks.md
"The damping lever" reports what it prints and why none of the implicit
variants is in the engine. Usage: scripts/damping_stability.py [--trials N]

With --split it checks the split scheme the engine has
(simulation.damping_scheme = "split", integrators/split_damping.hpp):

  split       v_t = v + dt*M^-1*(-K*x - (1 - theta)*C*v)
              v+  = v_t - theta*dt*M^-1*C*v_t,   x+ = x + dt*v+

at the step the engine takes, W(Xi)/omega_max with theta chosen for
Xi = beta*omega_max/2 (the same search, ported below), on networks whose
damping is proportional (C = beta*K, the case the engine's bound is proved
for) and on two the proof does not cover: each spring's dashpot kept or
dropped at random (joints slipping or open: C below beta*K), and each
spring's beta drawn in [beta/3, beta] (several [[joint]] laws; the step
takes the largest). It prints, per damping ratio, the worst spectral
radius at 0.999 of that step (stable: <= 1; at the step itself a network
whose top mode keeps no dashpot sits on the springs' own limit, 2/omega,
with a double root on the unit circle) and the worst ratio of each
network's own stable limit (scanned up from 0.999 W on a grid of 0.5 %) to
W: at least 0.999 when no network is unstable below the engine's step.
"""
import argparse

import numpy as np


def amplification(M, K, C, D, dt, theta, predicted):
    n = len(M)
    eye = np.eye(n)
    A = np.linalg.solve(np.diag(M) + dt * D, eye)
    dx = -dt * A @ K
    dv = -dt * A @ C
    if not predicted:  # state (x, v)
        T = np.block([[eye + dt * dx, dt * (eye + dv)], [dx, eye + dv]])
    else:  # state (x, v, dv_prev)
        dd = dt * A @ (D - theta * C)
        T = np.block([[eye + dt * dx, dt * (eye + dv), dt * dd], [dx, eye + dv, dd], [dx, dv, dd]])
    return np.max(np.abs(np.linalg.eigvals(T)))


def stable_limit(M, K, C, D, theta=0.0, predicted=False):
    """Largest omega*dt on a grid of 0.02 below which every step is stable."""
    w = np.sqrt(np.max(np.linalg.eigvals(np.linalg.solve(np.diag(M), K)).real))
    last = 0.0
    for s in np.arange(0.02, 4.0, 0.02):
        # 1e-6: rigid motions of unanchored groups give a double eigenvalue 1.
        if amplification(M, K, C, D, s / w, theta, predicted) > 1 + 1e-6:
            return last
        last = s
    return last


def random_network(rng):
    n = int(rng.integers(1, 9))
    K = np.zeros((n, n))
    for i in range(n):
        for j in range(i + 1, n):
            if rng.random() < 0.5:
                k = 10 ** rng.uniform(-1, 1)
                K[i, i] += k
                K[j, j] += k
                K[i, j] -= k
                K[j, i] -= k
        if rng.random() < 0.4:
            K[i, i] += 10 ** rng.uniform(-1, 1)
    K[0, 0] += 1.0
    M = 10 ** rng.uniform(-2, 1, n)
    return M, K


def split_stable(W, xi, theta):
    """The engine's exact check (split_damping.cpp): b >= 0, |ab| <= 1 and
    2 + 2ab - b*W^2 >= 0 for every dashpot X in [0, 2*xi*W]."""
    def least(c0, c1, c2, hi):
        m = min(c0, c0 + (c1 + c2 * hi) * hi)
        if c2 > 0:
            x = -c1 / (2 * c2)
            if 0 < x < hi:
                m = min(m, c0 + (c1 + c2 * x) * x)
        return m
    if W <= 0:
        return True
    xm = 2 * xi * W
    if 1 - theta * xm < 0:
        return False
    q = theta * (1 - theta)
    if least(1.0, -1.0, q, xm) < -1 or -least(-1.0, 1.0, -q, xm) > 1:
        return False
    return least(4 - W * W, theta * W * W - 2, 2 * q, xm) >= 0


def split_damping(xi):
    """The best theta of 0.01 .. 0.50 and its limit W (split_damping.cpp)."""
    best = (0.5, 0.0)
    for k in range(1, 51):
        theta = 0.01 * k
        lo, hi = 0.0, 2.0
        if split_stable(hi, xi, theta):
            lo = hi
        else:
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                if split_stable(mid, xi, theta):
                    lo = mid
                else:
                    hi = mid
        if lo > best[1]:
            best = (theta, lo)
    return best


def split_radius(M, K, C, dt, theta):
    n = len(M)
    eye = np.eye(n)
    A = dt * np.diag(1.0 / M)
    P = eye - theta * A @ C
    Q = eye - (1 - theta) * A @ C
    T = np.block([[eye - dt * P @ A @ K, dt * P @ Q], [-P @ A @ K, P @ Q]])
    return np.max(np.abs(np.linalg.eigvals(T)))


def random_springs(rng):
    """Spring matrices of a random network, one per spring (for dashpots per spring)."""
    n = int(rng.integers(1, 9))
    springs = []
    for i in range(n):
        for j in range(i + 1, n):
            if rng.random() < 0.5:
                k = 10 ** rng.uniform(-1, 1)
                S = np.zeros((n, n))
                S[i, i] = S[j, j] = k
                S[i, j] = S[j, i] = -k
                springs.append(S)
        if rng.random() < 0.4 or i == 0:
            S = np.zeros((n, n))
            S[i, i] = 10 ** rng.uniform(-1, 1)
            springs.append(S)
    M = 10 ** rng.uniform(-2, 1, n)
    return M, springs


def split_table(trials, seed):
    print("xi    case          theta  W      radius at 0.999 W  worst own limit / W   (networks: %d)" % trials)
    for xi in (0.2, 0.5, 0.83, 1.5):
        for case in ("proportional", "dropped", "mixed beta"):
            rng = np.random.default_rng(seed)
            worst_radius, worst_ratio, theta_w = 0.0, 9.0, None
            for _ in range(trials):
                M, springs = random_springs(rng)
                K = sum(springs)
                w = np.sqrt(np.max(np.linalg.eigvals(np.linalg.solve(np.diag(M), K)).real))
                beta = 2 * xi / w
                if case == "proportional":
                    C = beta * K
                elif case == "dropped":
                    C = sum(beta * S for S in springs if rng.random() < 0.5) + 0 * K
                else:
                    C = sum(beta * rng.uniform(1 / 3, 1) * S for S in springs)
                theta, W = split_damping(xi)
                theta_w = (theta, W)
                worst_radius = max(worst_radius, split_radius(M, K, C, 0.999 * W / w, theta))
                f = 0.999
                # 1e-6 as above: unanchored groups' double eigenvalue 1.
                while f < 3.0 and split_radius(M, K, C, (f + 0.005) * W / w, theta) <= 1 + 1e-6:
                    f += 0.005
                worst_ratio = min(worst_ratio, f)
            print(f"{xi:<5} {case:<13} {theta_w[0]:<6.2f} {theta_w[1]:<6.3f} {worst_radius:<18.6f} {worst_ratio:.3f}")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--trials", type=int, default=200, help="networks per damping ratio (default 200)")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--split", action="store_true", help="the split scheme's check instead (see above)")
    a = p.parse_args()
    if a.split:
        split_table(a.trials, a.seed)
        return
    print("xi    explicit(formula)  explicit  block  predicted theta=0  0.25  0.5   (worst omega*dt over the networks)")
    for xi in (0.2, 0.5, 0.83, 1.5):
        rng = np.random.default_rng(a.seed)
        worst = {}
        for _ in range(a.trials):
            M, K = random_network(rng)
            w = np.sqrt(np.max(np.linalg.eigvals(np.linalg.solve(np.diag(M), K)).real))
            C = (2 * xi / w) * K
            D = np.diag(np.diag(C))
            Z = np.zeros_like(C)
            runs = {"explicit": stable_limit(M, K, C, Z), "block": stable_limit(M, K, C, D)}
            for theta in (0.0, 0.25, 0.5):
                runs[theta] = stable_limit(M, K, C, D, theta, predicted=True)
            for k, v in runs.items():
                worst[k] = min(worst.get(k, 9.0), v)
        formula = 2 * (np.sqrt(1 + xi * xi) - xi)
        print(f"{xi:<5} {formula:<18.3f} {worst['explicit']:<9.2f} {worst['block']:<6.2f} "
              f"{worst[0.0]:<19.2f} {worst[0.25]:<5.2f} {worst[0.5]:.2f}")


if __name__ == "__main__":
    main()
