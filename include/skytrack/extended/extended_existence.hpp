#pragma once
// Existence probability of an extended track (a Bernoulli track's r, as in IPDA: Musicki,
// Evans & Stankovic 1994, IEEE Trans. AC 39(6), with a scan's partition of plots in place of
// one plot), kept as log-odds. It replaces the bare miss count for deleting confirmed tracks: a
// scan with plots raises it by the likelihood ratio of their count (an object's Poisson(gamma)
// plots against the clutter expected in the track's gate), a scan without lowers it by 1 - P_D', so
// a track that has shown its object many plots a scan survives a fade that deletes a track formed
// from a few clutter plots.
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

/// r from log-odds.
double existence_probability(double log_odds) noexcept;

}  // namespace skytrack::extended
