// Filtering a run's output channels: each output group at its channel frequency class
// (Model::output_filter_class), component by component, before anything is combined.
#pragma once

#include <string>
#include <vector>

#include "output/post/j211_filter.h"
#include "runtime/model/model.h"
#include "runtime/run/time_series.h"

namespace sled::runtime::post {

// The sample period of a run's rows.
double SamplePeriod(const Model& model);

// Column `column` (0 = the first channel, after time) of `series` filtered at class `cfc`;
// false with `error` when the sample rate is too low for the class.
bool FilterColumn(const TimeSeries& series, std::size_t column, double sample_period, double cfc,
                  FilterStandard standard, std::vector<double>& out, std::string* error);

// The first column (0 = the first channel) of every output group.
std::vector<std::size_t> GroupColumns(const Model& model);

struct FilteredChannels {
  TimeSeries series;                  // time, then each filtered channel under its own name
  std::vector<std::string> warnings;  // groups left unfiltered, and why
};

// Every channel of a group with a class, filtered; groups without one are left out.
FilteredChannels FilterOutputChannels(const Model& model, const TimeSeries& raw);

}  // namespace sled::runtime::post
