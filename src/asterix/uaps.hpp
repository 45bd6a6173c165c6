#pragma once
// User Application Profiles of the categories the decoder reads, and the FRNs of the items it
// interprets. Item formats and sizes from the EUROCONTROL category specifications: CAT001
// ed. 1.1 (plot and track UAPs), CAT002 ed. 1.0, CAT034 ed. 1.2x, CAT048 ed. 1.2x.
#include "record_walker.hpp"

namespace skytrack::asterix::detail {

extern const Uap kCat048Uap;
extern const Uap kCat001PlotUap;
extern const Uap kCat001TrackUap;
extern const Uap kCat002Uap;
extern const Uap kCat034Uap;

/// The name of an item for messages ("I048/040"), or "FRN n".
const char* item_name(const Uap& uap, int frn);

// FRNs of the interpreted items.
namespace cat048 {
inline constexpr int kDataSource = 1, kTimeOfDay = 2, kDescriptor = 3, kPolarPosition = 4,
                     kMode3a = 5, kFlightLevel = 6, kAircraftAddress = 8;
}
namespace cat001_plot {
inline constexpr int kDataSource = 1, kDescriptor = 2, kPolarPosition = 3, kMode3a = 4, kModeC = 5,
                     kTruncatedTime = 7;
}
namespace cat001_track {
inline constexpr int kDataSource = 1, kDescriptor = 2, kPolarPosition = 4, kMode3a = 7, kModeC = 8,
                     kTruncatedTime = 9;
}
namespace cat002 {
inline constexpr int kDataSource = 1, kMessageType = 2, kSector = 3, kTimeOfDay = 4,
                     kRotationPeriod = 5;
}
namespace cat034 {
inline constexpr int kDataSource = 1, kMessageType = 2, kTimeOfDay = 3, kSector = 4,
                     kRotationPeriod = 5, kPosition = 11;
}

}  // namespace skytrack::asterix::detail
