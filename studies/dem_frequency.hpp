// Model 6 of issue 4: the first natural frequency of the spire's block model
// on its joints, measured by a small free vibration in the DEM, against the
// tapered-cantilever estimate of eq. 4 with the joint stiffness lumped into an
// equivalent modulus E_eq = kn · course height (rigid stones: all the
// deformation is in the joints, one joint per course).
//
// The run: the deck's spire under gravity with joint damping β = 0 (unless
// kept), a one-sine ground-acceleration pulse a_p sin(2π(t − t0)/T_p) after
// `settle_time`, then free vibration for `duration`. The tip block's
// horizontal displacement along the pulse after the pulse ends is the signal;
// its first frequency is the peak of its Hann-windowed Fourier amplitude
// (scanned, then refined by golden section on the continuous transform) and,
// as a check, the mean spacing of its zero crossings.
#pragma once

#include <string>
#include <vector>

#include "analytical/shell_sections.hpp"
#include "core/scene_spec.hpp"

namespace polydem {

struct DemFrequencyOptions {
  double settle_time = 0.05;       // s under gravity before the pulse
  double duration = 0.5;           // s of free vibration recorded after the pulse
  double pulse_g = 0.005;          // pulse amplitude, in g
  double pulse_period = 0.02;      // s
  double history_interval = 2e-4;  // s between samples of the tip's position
  double azimuth = 0.0;            // rad, pulse direction from +x
  bool keep_damping = false;       // false: joint.damping = 0
  double f_min = 1.0, f_max = 200.0;  // Hz, the Fourier scan
  int threads = 0;
};

struct DemFrequencyResult {
  std::string tip;               // the monitored block
  double f_fourier_hz = 0.0;     // peak of the windowed Fourier amplitude
  double f_zero_crossing_hz = 0.0;
  int zero_crossings = 0;
  double amplitude_m = 0.0;      // largest |u| after the pulse
  double window_s = 0.0;         // length of the analysed signal
  int samples = 0;
  // The beam estimate (eq. 4, Ω1) with E_eq = kn · course height.
  double kn = 0.0, course_height = 0.0, E_eq = 0.0, density = 0.0;
  double outer_apothem = 0.0, wall_thickness = 0.0, height = 0.0, Omega1 = 0.0;
  analytical::ShellSection section;
  double f_beam_hz = 0.0;
  double ratio_to_beam = 0.0;    // f_fourier_hz / f_beam_hz (0 without a beam frequency)
  // The run.
  std::string status;
  bool unstable = false;
  std::string instability;
  long steps = 0;
  double time_step = 0.0, wall_seconds = 0.0, end_time = 0.0;
  int blocks = 0;
  std::vector<double> t, u;  // the analysed signal (s, m)
};

// The normal stiffness of the joints among the spire's free stones (the
// beam estimate's kn), from the deck's laws: [joint] and every [[joint]]
// between that acts among them. Throws std::runtime_error when they differ.
double spire_joint_normal_stiffness(const SceneSpec& scene);

// The first block named "tip", else the highest free block.
std::string spire_tip_block(const SceneSpec& scene);

// Runs the scene as described above (changes to a copy: ground motion,
// histories, damping, end time, no early settle stop). Needs a [spire].
// Throws std::runtime_error (no spire, run failure).
DemFrequencyResult measure_dem_frequency(SceneSpec scene, const DemFrequencyOptions& options = {});

// The frequency analysis alone (uniform or not: the transform is a sum over
// the samples with trapezoid weights). Returns the peak in [f_min, f_max].
double fourier_peak_hz(const std::vector<double>& t, const std::vector<double>& u, double f_min, double f_max);
// (crossings − 1) / (2 (t_last − t_first)); 0 with fewer than 3 crossings.
double zero_crossing_hz(const std::vector<double>& t, const std::vector<double>& u, int* crossings = nullptr);

}  // namespace polydem
