#include "output/post/channel_filters.h"

#include <fmt/format.h>

#include "runtime/run/outputs.h"

namespace sled::runtime::post {

double SamplePeriod(const Model& model) {
  return model.output_every > 0 ? model.output_every : model.end_time - model.start_time;
}

bool FilterColumn(const TimeSeries& series, std::size_t column, double sample_period, double cfc,
                  FilterStandard standard, std::vector<double>& out, std::string* error) {
  std::vector<double> signal(series.rows());
  for (std::size_t row = 0; row < series.rows(); ++row) {
    signal[row] = series.values[row * series.columns + 1 + column];
  }
  return FilterCfc(signal, sample_period, cfc, standard, out, error);
}

std::vector<std::size_t> GroupColumns(const Model& model) {
  std::vector<std::size_t> first(model.output_kind.size());
  std::size_t column = 0;
  for (std::size_t k = 0; k < model.output_kind.size(); ++k) {
    first[k] = column;
    column += ChannelCount(model, k);
  }
  return first;
}

FilteredChannels FilterOutputChannels(const Model& model, const TimeSeries& raw) {
  FilteredChannels result;
  const double period = SamplePeriod(model);
  const std::vector<std::size_t> first = GroupColumns(model);
  std::vector<std::size_t> kept;  // raw channel columns that are filtered
  std::vector<std::vector<double>> filtered;
  for (std::size_t k = 0; k < model.output_kind.size(); ++k) {
    const int cfc = k < model.output_filter_class.size() ? model.output_filter_class[k] : 0;
    if (cfc <= 0) continue;
    const FilterStandard standard =
        k < model.output_filter_iso.size() && model.output_filter_iso[k] != 0
            ? FilterStandard::kIso6487
            : FilterStandard::kSaeJ211;
    const std::size_t count = ChannelCount(model, k);
    std::string error;
    std::vector<std::vector<double>> group(count);
    bool ok = true;
    for (std::size_t c = 0; c < count && ok; ++c) {
      ok = FilterColumn(raw, first[k] + c, period, cfc, standard, group[c], &error);
    }
    if (!ok) {
      result.warnings.push_back(
          fmt::format("output `{}` is not filtered: {}", model.output_label[k], error));
      continue;
    }
    for (std::size_t c = 0; c < count; ++c) {
      kept.push_back(first[k] + c);
      filtered.push_back(std::move(group[c]));
    }
  }
  TimeSeries& series = result.series;
  for (const std::size_t column : kept) series.names.push_back(raw.names[column]);
  series.columns = 1 + kept.size();
  series.values.resize(raw.rows() * series.columns);
  for (std::size_t row = 0; row < raw.rows(); ++row) {
    series.values[row * series.columns] = raw.values[row * raw.columns];
    for (std::size_t c = 0; c < kept.size(); ++c) {
      series.values[row * series.columns + 1 + c] = filtered[c][row];
    }
  }
  return result;
}

}  // namespace sled::runtime::post
