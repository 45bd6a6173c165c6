#include "multi_scenario.hpp"
namespace skytrack::extended::experiment {
void print_multi_table(const Eigen::Matrix2d&, int, std::uint64_t) {}
}  // namespace skytrack::extended::experiment
