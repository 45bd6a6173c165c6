#pragma once
// Existence probability of an extended track (a Bernoulli track's r, as in IPDA: Musicki,
// Evans & Stankovic 1994, IEEE Trans. AC 39(6), with a scan's partition of plots in place of
// one plot), kept as log-odds. It replaces the bare miss count for deleting confirmed tracks: a
// scan with plots raises it by the likelihood ratio of their count (an object's Poisson(gamma)
// plots against the clutter expected in the track's gate), a scan without lowers it by 1 - P_D', so
// a track that has shown its object many plots a scan survives a fade that deletes a track formed
// from a few clutter plots.
#include <span>

#include <Eigen/Core>

#include "skytrack/extended/extended_spec.hpp"

namespace skytrack::extended {

/// Log-odds ln(r / (1 - r)) of a new track.
double existence_birth(const ExistenceSpec& spec) noexcept;

/// Prediction over one scan: r -> p_s r, p_s the survival probability per scan.
double existence_predict(double log_odds, const ExistenceSpec& spec) noexcept;

/// A scan in which the track took `plots` plots (>= min_plots) from a gate of
/// `gate_area` [m^2]: log-odds + ln L, L = P_D Poisson(n; gamma) / Poisson(n; lambda A).
double existence_hit(double log_odds, int plots, double gate_area,
                     const ExistenceSpec& spec) noexcept;

/// A scan without plots: log-odds + ln(1 - P_D'), P_D' = P_D P(n >= min_plots | gamma) the
/// probability the object gives the tracker a usable partition.
double existence_miss(double log_odds, int min_plots, const ExistenceSpec& spec) noexcept;

/// ln of the likelihood ratio that a scan's n plots in a track's gate are its object's, seen,
/// against the object missed and the plots clutter:
///   ln [P_D e^{-gamma} gamma^n f(z_1..z_n) / ((1 - P_D) lambda^n)],
/// f the plots' joint density when each is the centre plus a scatter of covariance S and
/// the centre is N(`centre`, `centre_cov` = C): the centre is shared, so f = N(mean; centre,
/// C + S/n) times the density of the deviations about the mean, (2 pi)^-(n-1) |S'|^-(n-1)/2
/// n^-1 exp(-1/2 sum (z_i - mean)' S'^-1 (z_i - mean)). The object's extent is not known,
/// so the deviations are taken under S' = `spread` (the predicted X/4 + R) plus the plots'
/// own sample covariance: an extent estimate smaller than the object (SMF-EOT's inner one on
/// a few plots) does not turn its plots into clutter; a pair far from the predicted centre,
/// in a scan with little evidence, does.
/// -infinity when a covariance is not positive definite or there are no plots.
double object_plots_log_ratio(std::span<const Eigen::Vector2d> plots, const Eigen::Vector2d& centre,
                              const Eigen::Matrix2d& centre_cov, const Eigen::Matrix2d& spread,
                              const ExistenceSpec& spec) noexcept;
/// ln f of object_plots_log_ratio alone (the plots' joint density under one object).
double object_plots_log_density(std::span<const Eigen::Vector2d> plots,
                                const Eigen::Vector2d& centre, const Eigen::Matrix2d& centre_cov,
                                const Eigen::Matrix2d& spread) noexcept;
/// A track's model of its object's plots in a scan: centre N(centre, centre_cov), each plot
/// scattered about it by `spread` (X/4 + R).
struct PlotsModel {
  Eigen::Vector2d centre;
  Eigen::Matrix2d centre_cov, spread;
};
/// ln of the likelihood ratio of a split of one partition between two tracks (`own` plots to
/// the first, `other` to the second, both objects seen) against the first's object missed and
/// the second's giving all of them:
///   ln [P_D / (1 - P_D) e^{-gamma} f_1(own) f_2(other) / f_2(own + other)]
/// (object_plots_log_density; the counts' gamma^n cancel). -infinity when either share is
/// empty.
double split_log_ratio(std::span<const Eigen::Vector2d> own, std::span<const Eigen::Vector2d> other,
                       const PlotsModel& own_model, const PlotsModel& other_model,
                       const ExistenceSpec& spec);
/// ln of the likelihood ratio of a two-track split exchanged (`own` plots to the second
/// track, `other` to the first) against the split as given:
///   ln [f_1(other) f_2(own) / (f_1(own) f_2(other))]   (object_plots_log_density).
/// Positive: the exchanged split is the likelier. -infinity when either share is empty.
double exchange_log_ratio(std::span<const Eigen::Vector2d> own,
                          std::span<const Eigen::Vector2d> other, const PlotsModel& own_model,
                          const PlotsModel& other_model);
/// r from log-odds.
double existence_probability(double log_odds) noexcept;

}  // namespace skytrack::extended
