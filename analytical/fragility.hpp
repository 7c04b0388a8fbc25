#pragma once
// Lognormal fragility curves from dynamic analyses (docs/fragility.md).
//
// A fragility curve is the probability that a structure reaches a damage
// state ds (or a worse one) under a ground motion of intensity IM = x:
//
//     P(DS ≥ ds | IM = x) = Φ( ln(x / θ) / β )
//
// θ is the median capacity (the IM at which half the motions reach ds) and
// β the dispersion of ln capacity. Two kinds of analyses give the data:
//
// - Incremental dynamic analysis (IDA): each record is scaled up until the
//   state is reached; the record's capacity is the lowest IM at which it
//   was. The capacities are a sample of a lognormal variable; a record that
//   never reaches the state up to the largest IM tried only says that its
//   capacity is above that IM (right-censored). The maximum likelihood
//   estimate maximises Σ ln f(ln cᵢ) over the capacities plus
//   Σ ln(1 − Φ((ln cⱼ − ln θ)/β)) over the censored records; without
//   censoring it is the log-moments ln θ = mean ln cᵢ,
//   β² = (1/n) Σ (ln cᵢ − ln θ)² (the MLE: 1/n, not 1/(n − 1)).
// - Multiple-stripe analysis (MSA): at each of a few IM levels xⱼ, nⱼ runs,
//   zⱼ of which reach the state. Baker (2015, Earthquake Spectra 31(1),
//   "Efficient analytical fragility function fitting using dynamic
//   structural analysis") fits θ, β by maximising the binomial likelihood
//   Σ zⱼ ln Φ(·) + (nⱼ − zⱼ) ln(1 − Φ(·)): the runs that do not reach the
//   state count as much as those that do, and stripes need not reach 100 %.
//
// Several damage states are fitted separately (damaged, stones lost,
// collapsed; a run's state is the worst it reached, so reaching "collapsed"
// also reaches "damaged").
//
// Confidence bands come from a seeded bootstrap: B resamples of the records
// (IDA) or of the runs within each stripe (MSA, a binomial draw with the
// stripe's observed fraction), each refitted; the band at each IM is the
// pair of percentiles (1 ∓ confidence)/2 of the resampled curves, and so
// for θ and β. A resample whose fit does not exist (no record reached the
// state, or the runs are perfectly separated) is counted and left out.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace polydem::analytical {

// Ordered by severity; a run's state is the worst it reached.
enum class DamageState { intact = 0, damaged = 1, stones_lost = 2, collapsed = 3 };
const char* to_string(DamageState s);
// "intact", "damaged", "stones_lost" (or "stones-lost"), "collapsed", or 0-3.
std::optional<DamageState> damage_state_named(std::string_view name);

// P = Φ(ln(x/θ)/β); x ≤ 0 gives 0.
struct LognormalFragility {
  double theta = 0.0;  // median capacity, in the IM's unit
  double beta = 0.0;   // dispersion of ln capacity
};
double fragility_probability(const LognormalFragility& f, double im);

// Lognormal MLE from capacities and right-censored values (all > 0);
// nullopt when it does not exist: no capacity, or every capacity equal
// with nothing censored above them.
std::optional<LognormalFragility> fit_capacities(const std::vector<double>& capacities,
                                                 const std::vector<double>& censored);

// One stripe: `runs` runs at intensity `im`, `reached` of them reaching the state.
struct Stripe {
  double im = 0.0;
  int runs = 0;
  int reached = 0;
};
// Baker's binomial MLE; nullopt when no finite maximum exists (no run or
// every run reached the state, or the stripes are separated: all the runs
// below some IM do not reach it and all above do).
std::optional<LognormalFragility> fit_stripes(const std::vector<Stripe>& stripes);

// One dynamic run: the record's name (empty for stripes), its IM and the
// worst state it reached.
struct FragilityRun {
  std::string record;
  double im = 0.0;
  DamageState state = DamageState::intact;
};

enum class FragilityMethod { ida, stripes };
const char* to_string(FragilityMethod m);

struct FragilityOptions {
  FragilityMethod method = FragilityMethod::ida;
  int bootstrap = 1000;       // resamples; 0: no band
  std::uint64_t seed = 1;     // state j's resamples use mix_seed(seed, j)
  double confidence = 0.90;   // the band's two-sided level, in (0, 1)
  int points = 101;           // IM grid, from 0 to 1.25 × the largest IM run
};

enum class FitStatus { fitted, none_reached, all_reached, not_identified };
const char* to_string(FitStatus s);

// The data behind one curve, for a plot: IDA, one point per record (its
// capacity, or the IM it was censored at); MSA, one per stripe.
struct FragilityPoint {
  std::string record;  // IDA
  double im = 0.0;
  int runs = 1;
  int reached = 0;     // IDA: 1 if the record reached the state
};

struct FragilityCurveFit {
  DamageState state = DamageState::damaged;
  FitStatus status = FitStatus::fitted;
  LognormalFragility curve;  // NaN unless fitted
  double theta_low = 0.0, theta_high = 0.0, beta_low = 0.0, beta_high = 0.0;  // NaN without a band
  int observations = 0;  // records (IDA) or runs (MSA)
  int reached = 0;       // of them, those that reached the state
  int bootstrap_fitted = 0;  // resamples with a fit
  std::vector<double> probability, band_low, band_high;  // on FragilityResult::im
  std::vector<FragilityPoint> points;
};

struct FragilityResult {
  FragilityOptions options;
  std::vector<double> im;                  // the grid of the curves
  std::vector<FragilityCurveFit> states;   // damaged, stones lost, collapsed
};

// Fits damaged, stones_lost and collapsed. Throws std::invalid_argument on
// bad input: no runs, an IM ≤ 0 or not finite, IDA without record names,
// options out of range. A state that cannot be fitted gets its status
// (none_reached: θ is above every IM run; all_reached: θ is below the
// lowest; not_identified: separated stripes or equal capacities) and NaN
// curves; the others are fitted regardless.
FragilityResult fit_fragility(const std::vector<FragilityRun>& runs, const FragilityOptions& options);

}  // namespace polydem::analytical
