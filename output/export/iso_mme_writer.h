// Writing a run as an ISO-MME data set (ISO/TS 13499, version 1.6; `sled run --format iso-mme`):
//
//   DIR/<test>.mme              test header
//   DIR/Channel/<test>.chn      channel index: the number of channels, each one's code and name
//   DIR/Channel/<test>.001 ...  one file per channel: header lines `Name (padded to 28):value`,
//                               then one sample per line
//
// The channels are the raw output channels (filter class 0), the filtered ones (class letter
// of their CFC) and the injury criteria as one-sample channels of class X, coded as
// iso_mme_codes.h says. Values are in SI units as sled computes them (criteria in their own
// units), written with the shortest text that reads back to the same double.
#pragma once

#include <string>
#include <vector>

#include "output/post/criterion_value.h"
#include "runtime/model/model.h"
#include "runtime/run/time_series.h"

namespace sled::runtime {

// `test` names the data set (the file stem of the .mme); false with `error` set when a file
// cannot be written.
bool WriteIsoMme(const std::string& directory, const std::string& test, const Model& model,
                 const TimeSeries& raw, const TimeSeries& filtered,
                 const std::vector<post::CriterionValue>& criteria, std::string* error);

}  // namespace sled::runtime
