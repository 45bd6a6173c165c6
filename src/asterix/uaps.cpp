#include "uaps.hpp"

#include <array>

namespace skytrack::asterix::detail {
namespace {

// I048/130 Radar Plot Characteristics: SRL SRR SAM PRL PAM RPD APD, one octet each.
constexpr std::array<ItemSpec, 7> k048_130{fixed(1), fixed(1), fixed(1), fixed(1),
                                           fixed(1), fixed(1), fixed(1)};
// I048/120 Radial Doppler Speed: CAL (2 octets), RDS (REP x (DOP, AMB, FRQ) = 6 octets).
constexpr std::array<ItemSpec, 2> k048_120{fixed(2), repetitive(6)};

constexpr std::array<ItemSpec, 28> k048{
    fixed(2), fixed(3),           extended(1),        fixed(4),  // 010 140 020 040
    fixed(2), fixed(2),           compound(k048_130),            // 070 090 130
    fixed(3), fixed(6),           repetitive(8),      fixed(2),  // 220 240 250 161
    fixed(4), fixed(4),           extended(),                    // 042 200 170
    fixed(4), extended(),         fixed(2),           fixed(4),  // 210 030 080 100
    fixed(2), compound(k048_120), fixed(2),                      // 110 120 230
    fixed(7), fixed(1),           fixed(2),           fixed(1),  // 260 055 050 065
    fixed(2), explicit_length(),  explicit_length()};            // 060 SP RE
const char* const k048Names[] = {
    "I048/010", "I048/140", "I048/020", "I048/040", "I048/070", "I048/090", "I048/130",
    "I048/220", "I048/240", "I048/250", "I048/161", "I048/042", "I048/200", "I048/170",
    "I048/210", "I048/030", "I048/080", "I048/100", "I048/110", "I048/120", "I048/230",
    "I048/260", "I048/055", "I048/050", "I048/065", "I048/060", "I048/SP",  "I048/RE"};

constexpr std::array<ItemSpec, 21> k001Plot{
    fixed(2),          extended(),     fixed(4),    fixed(2),    fixed(2),
    extended(),        fixed(2),  // 010..141
    fixed(2),          fixed(1),       fixed(1),    fixed(2),    fixed(4),
    fixed(2),          extended(),                                             // 050..030
    fixed(1),          undefined(),    undefined(), undefined(), undefined(),  // 150, spares
    explicit_length(), random_fields()};                                       // SP RFS
const char* const k001PlotNames[] = {
    "I001/010", "I001/020", "I001/040", "I001/070", "I001/090", "I001/130", "I001/141",
    "I001/050", "I001/120", "I001/131", "I001/080", "I001/100", "I001/060", "I001/030",
    "I001/150", "spare",    "spare",    "spare",    "spare",    "I001/SP",  "I001/RFS"};

constexpr std::array<ItemSpec, 22> k001Track{
    fixed(2),        extended(), fixed(2),   fixed(4), fixed(4),   fixed(4),
    fixed(2),  // 010..070
    fixed(2),        fixed(2),   extended(), fixed(1), fixed(1),   extended(),
    extended(),                                                                        // 090..210
    fixed(2),        fixed(2),   fixed(4),   fixed(2), extended(), explicit_length(),  // 050..SP
    random_fields(), fixed(1)};                                                        // RFS 150
const char* const k001TrackNames[] = {
    "I001/010", "I001/020", "I001/161", "I001/040", "I001/042", "I001/200", "I001/070", "I001/090",
    "I001/141", "I001/130", "I001/131", "I001/120", "I001/170", "I001/210", "I001/050", "I001/080",
    "I001/100", "I001/060", "I001/030", "I001/SP",  "I001/RFS", "I001/150"};

constexpr std::array<ItemSpec, 14> k002{fixed(2),       fixed(1),          fixed(1),   fixed(3),
                                        fixed(2),       extended(),        extended(),  // 010..060
                                        repetitive(2),  fixed(8),          fixed(2),   extended(),
                                        undefined(),    explicit_length(),  // 070..SP
                                        random_fields()};
const char* const k002Names[] = {"I002/010", "I002/000", "I002/020", "I002/030", "I002/041",
                                 "I002/050", "I002/060", "I002/070", "I002/100", "I002/090",
                                 "I002/080", "spare",    "I002/SP",  "I002/RFS"};

// I034/050 System Configuration and Status: COM, -, -, PSR, SSR, MDS (2 octets).
constexpr std::array<ItemSpec, 6> k034_050{fixed(1), undefined(), undefined(),
                                           fixed(1), fixed(1),    fixed(2)};
// I034/060 System Processing Mode: COM, -, -, PSR, SSR, MDS (1 octet each).
constexpr std::array<ItemSpec, 6> k034_060{fixed(1), undefined(), undefined(),
                                           fixed(1), fixed(1),    fixed(1)};
constexpr std::array<ItemSpec, 14> k034{
    fixed(2),           fixed(1),          fixed(3),         fixed(1), fixed(2),
    compound(k034_050),                                                           // 010..050
    compound(k034_060), repetitive(2),     fixed(8),         fixed(1), fixed(8),  // 060..120
    fixed(2),           explicit_length(), explicit_length()};                    // 090 RE SP
const char* const k034Names[] = {"I034/010", "I034/000", "I034/030", "I034/020", "I034/041",
                                 "I034/050", "I034/060", "I034/070", "I034/100", "I034/110",
                                 "I034/120", "I034/090", "I034/RE",  "I034/SP"};

}  // namespace

const Uap kCat048Uap{k048.data(), static_cast<int>(k048.size()), k048Names};
const Uap kCat001PlotUap{k001Plot.data(), static_cast<int>(k001Plot.size()), k001PlotNames};
const Uap kCat001TrackUap{k001Track.data(), static_cast<int>(k001Track.size()), k001TrackNames};
const Uap kCat002Uap{k002.data(), static_cast<int>(k002.size()), k002Names};
const Uap kCat034Uap{k034.data(), static_cast<int>(k034.size()), k034Names};

const char* item_name(const Uap& uap, int frn) {
  if (frn >= 1 && frn <= uap.count && uap.names != nullptr) return uap.names[frn - 1];
  return "FSPEC";
}

}  // namespace skytrack::asterix::detail
