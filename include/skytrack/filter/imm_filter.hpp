#pragma once
// Interacting multiple model filter with PDA/JPDA measurement weights
// (Blom & Bar-Shalom 1988; paper 003 §3.1 eq. 1-7 and §3.2 eq. 8-10).
//   mixing      c_j = sum_i p_ij mu_i,  mu_i|j = p_ij mu_i / c_j                (eq. 1-2)
//               x0j = sum_i mu_i|j x_i,  P0j = sum_i mu_i|j (P_i + dx dx')
//   prediction  each mode with its own motion model (motion/motion_model.hpp)
//   update      per mode: the PDA update (filter/pda.hpp) with the mode's own weights,
//               beta_ij ~ beta_i N_ij / L_i and beta_0j ~ beta_0 (below)
//   mode prob.  eq. 3-5 extended to data association, see below
//   output      x = sum_j mu_j x_j,  P = sum_j mu_j (P_j + dx dx')               (eq. 6-7)
//
// Mode probabilities under association uncertainty. With plot likelihoods
// N_ij = N(nu_ij; 0, S_ij) (eq. 3) and the IMM-weighted plot likelihood
// L_i = sum_j c_j N_ij that the JPDA events are evaluated with (eq. 8-10),
//   mu_j = P(M_j | Z) = sum_theta P(M_j | theta, Z) beta_theta
//        = c_j (beta_0 + sum_i beta_i N_ij / L_i),
// because under the miss hypothesis no mode is favoured (P(M_j | theta_0) = c_j) and under
// "plot i is the target's" it is eq. 4-5 with that plot (c_j N_ij / L_i). This
//   * reduces to eq. 3-5 exactly for one plot with beta_1 = 1;
//   * for an isolated track whose beta are the PDA weights (pda_weights) equals the
//     standard IMM-PDA form mu_j ~ c_j Lambda_j,
//     Lambda_j = (1 - PD PG) + (PD / lambda) sum_i N_ij (the IMM-PDAF of Houles &
//     Bar-Shalom 1989, IEEE Trans. AES-25(2)), since beta_0 and beta_i share its normaliser;
//   * in a JPDA cluster uses the same marginals as the state update, so a plot that another
//     track most likely owns does not drive this track's mode probabilities.
// Each mode's state is updated with the same decomposition: given M_j, the event "plot i"
// has probability P(theta_i | M_j, Z) = beta_i (N_ij / L_i) / (mu_j / c_j), and the miss
// beta_0 / (mu_j / c_j). For an isolated track these are the mode-matched PDAF's own
// weights (IMM-PDAF); with one mode, or one plot and no miss, they are the track's beta.
// So the implemented form is the beta-weighted one; PD, PG and lambda are used only when the
// given weights are unusable (sum <= 0 or not finite): the track is then treated as isolated
// and weighted by pda_weights.
//
// Numerics: a mode whose innovation for a plot with beta_i > 0 failed (S not positive
// definite) keeps its prediction and sets its bit in failed_modes; its N_ij count as 0.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/filter/innovation.hpp"
#include "skytrack/filter/state.hpp"
#include "skytrack/measurement/plot_measurement.hpp"
#include "skytrack/motion/motion_model.hpp"

namespace skytrack {

inline constexpr int kMaxImmModes = 32;

struct ImmEstimate {
  std::vector<Gaussian> modes;     // one per mode, all in the filter's StateLayout
  Eigen::VectorXd probabilities;   // mu_j (posterior) or c_j (after predict)
  double time = 0.0;               // [s]
  std::uint32_t failed_modes = 0;  // bit j: mode j kept its prediction (numeric failure)

  bool numeric_failure() const noexcept { return failed_modes != 0; }
};

/// One plot evaluated against every mode of one track's prediction.
struct PlotHypothesis {
  std::vector<Innovation> per_mode;
  double likelihood = 0.0;      // L = sum_j c_j N(nu_j; 0, S_j): what JPDA weighs events with
  double log_likelihood = 0.0;  // log L (finite far beyond where L underflows); -inf if unusable
  double max_nis = 0.0;         // over the usable modes
  double min_nis = 0.0;         // over the usable modes (union-of-gates test)
  bool usable = false;          // at least one mode's innovation is ok
};

/// The innovation shapes (innovation.hpp) of one prediction's modes for one measurement
/// model: hypothesise() makes them for the first plot and reuses them for the next plots of
/// the same model. Clear it whenever the prediction changes.
class HypothesisShapes {
 public:
  void clear() noexcept { valid_ = false; }

 private:
  friend class ImmFilter;
  bool valid_ = false;
  MeasurementModel model_;
  std::vector<InnovationShape> modes_;
};

class ImmFilter {
 public:
  /// `transition`: Markov matrix p_ij = P(mode j now | mode i before), rows sum to 1, given
  /// for predictions over `transition_interval` seconds (0: applied once per prediction,
  /// whatever its length). The arguments must be valid (create() checks them; the
  /// constructor only asserts).
  ImmFilter(std::vector<AnyMotionModel> models, std::vector<std::string> names,
            Eigen::MatrixXd transition, StateLayout layout, config::MeasurementSpec measurement,
            double transition_interval = 0.0);

  /// Checks sizes, the Markov matrix, the layout against the models, and the parameters.
  static Expected<ImmFilter> create(std::vector<AnyMotionModel> models,
                                    std::vector<std::string> names, Eigen::MatrixXd transition,
                                    StateLayout layout, config::MeasurementSpec measurement,
                                    double transition_interval = 0.0);
  /// The profile's models, Markov matrix and measurement settings, in the profile's
  /// dimension, or in `auto_dims` when the profile leaves it to the plots (dimension 0).
  static Expected<ImmFilter> from_profile(const config::TrackingProfile& profile,
                                          int auto_dims = 3);

  /// Every mode starts at `state`; probabilities are normalised (uniform if unusable).
  ImmEstimate initial(const Gaussian& state, const Eigen::VectorXd& probabilities,
                      double time) const;

  /// Mixing (eq. 1-2) and per-mode prediction to `time`; the result's probabilities are the
  /// predicted c_j. A prediction over more than one transition interval is made interval by
  /// interval, the remainder last, mixing before each step (a manoeuvre can begin within
  /// it); each step's Markov matrix is transition_over its length, so c is transition_over
  /// the whole prediction.
  ImmEstimate predict(const ImmEstimate& posterior, double time) const noexcept;
  /// The same, written over `out` (another object than `posterior`), whose storage is reused.
  void predict(const ImmEstimate& posterior, double time, ImmEstimate& out) const noexcept;

  /// The prediction of `posterior` taken as certain of `mode` (mu one there, zero elsewhere):
  /// that mode's estimate along its own model, set as every mode's estimate (one prediction,
  /// not one per mode), with the mode priors such a certainty gives.
  ImmEstimate predict_certain(const ImmEstimate& posterior, int mode, double time) const noexcept;
  void predict_certain(const ImmEstimate& posterior, int mode, double time,
                       ImmEstimate& out) const noexcept;

  /// Innovations of one plot against every mode of a prediction.
  PlotHypothesis hypothesise(const ImmEstimate& predicted,
                             const PlotMeasurement& measurement) const noexcept;
  /// The same, with the plot-independent parts kept in `shapes` across the plots of one
  /// prediction (EKF updates; the unscented update innovates each plot whole).
  PlotHypothesis hypothesise(const ImmEstimate& predicted, const PlotMeasurement& measurement,
                             HypothesisShapes& shapes) const noexcept;
  /// The smallest NIS of a plot over the modes whose innovation is ok (+infinity when none
  /// is), as hypothesise() gives it, from the kept shapes without the rest of the
  /// hypothesis: the cheap test of whether a plot lies in any mode's gate (the unscented
  /// update has no shortcut: it innovates the plot whole).
  double min_nis(const ImmEstimate& predicted, const PlotMeasurement& measurement,
                 HypothesisShapes& shapes) const noexcept;

  /// Per-mode PDA update with the track's association weights and the mode probabilities
  /// described at the top of this file. hypotheses[i] pairs with beta_plots[i]; the weights
  /// are renormalised with beta_miss to sum to 1.
  ImmEstimate update(const ImmEstimate& predicted, std::span<const PlotHypothesis> hypotheses,
                     std::span<const double> beta_plots, double beta_miss,
                     double detection_probability, double gate_probability,
                     double clutter_density) const noexcept;
  /// The same, written over `out` (another object than `predicted`), whose storage is reused.
  void update(const ImmEstimate& predicted, std::span<const PlotHypothesis> hypotheses,
              std::span<const double> beta_plots, double beta_miss, double detection_probability,
              double gate_probability, double clutter_density, ImmEstimate& out) const noexcept;

  /// The Markov matrix over `dt` seconds: P^k (I + f (P - I)) with k + f = dt / interval
  /// (k whole), a stochastic matrix equal to P at dt = interval and to I at dt = 0; P itself
  /// when the interval is 0. Backward predictions (dt < 0) switch no mode.
  Eigen::MatrixXd transition_over(double dt) const;

  /// Combined estimate, eq. 6-7.
  Gaussian combine(const ImmEstimate& estimate) const noexcept;

  const std::vector<std::string>& names() const { return names_; }
  const std::vector<AnyMotionModel>& models() const { return models_; }
  const Eigen::MatrixXd& transition() const { return transition_; }
  double transition_interval() const { return transition_interval_; }
  const StateLayout& layout() const { return layout_; }
  const config::MeasurementSpec& measurement_spec() const { return measurement_; }
  int mode_count() const { return static_cast<int>(models_.size()); }

 private:
  /// A prediction longer than the transition interval is made in steps of one interval and
  /// the remainder (a very long one in a bounded number of equal steps), mixing between
  /// steps; `certain` >= 0 predicts in one step.
  void predict_modes(const ImmEstimate& posterior, double time, int certain,
                     ImmEstimate& out) const noexcept;
  /// Mixing and per-mode prediction over one step, the Markov matrix taken over its length.
  void predict_step(const ImmEstimate& posterior, double time, int certain,
                    ImmEstimate& out) const noexcept;
  /// The kept shapes, remade when `measurement` has another model than the last plot's.
  void shape(const ImmEstimate& predicted, const PlotMeasurement& measurement,
             HypothesisShapes& shapes) const noexcept;
  /// A hypothesis' likelihood (mixed over the modes' priors) and NIS range from its per_mode.
  void weigh(const ImmEstimate& predicted, PlotHypothesis& out) const noexcept;
  std::vector<AnyMotionModel> models_;
  // Each mode's last discretisations (a cache: predictions stay const; one filter per thread).
  mutable std::vector<DiscretisationMemo> memos_;
  std::vector<std::string> names_;
  Eigen::MatrixXd transition_;
  double transition_interval_ = 0.0;
  StateLayout layout_;
  config::MeasurementSpec measurement_;
};

}  // namespace skytrack
