#pragma once
#include <cstdint>

#include <Eigen/Core>

namespace skytrack::extended::experiment {
void print_multi_table(const Eigen::Matrix2d& bayes_noise, int runs, std::uint64_t seed);
}
