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


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--trials", type=int, default=200, help="networks per damping ratio (default 200)")
    p.add_argument("--seed", type=int, default=1)
    a = p.parse_args()
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
