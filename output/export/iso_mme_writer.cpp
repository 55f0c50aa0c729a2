#include "output/export/iso_mme_writer.h"

#include <cmath>
#include <ctime>
#include <filesystem>

#include <fmt/format.h>

#include "output/atomic_file.h"
#include "output/export/iso_mme_codes.h"
#include "output/number_text.h"
#include "output/post/channel_filters.h"

namespace sled::runtime {
namespace {

// `Name                        :value`: the name padded to 28 characters.
std::string Field(const std::string& name, const std::string& value) {
  return fmt::format("{:<28}:{}\n", name, value);
}

std::string Number(double value) {
  if (!std::isfinite(value)) return "NOVALUE";
  std::string text;
  AppendShortest(text, value);
  return text;
}

bool WriteFile(const std::filesystem::path& path, const std::string& text, std::string* error) {
  return ReplaceFile(path.string(), text, error);
}

std::string Today() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  return fmt::format("{:04}-{:02}-{:02}", local.tm_year + 1900, local.tm_mon + 1, local.tm_mday);
}

// The header lines every channel file starts with.
std::string ChannelHeader(const IsoMmeChannel& channel, int cfc, double first_time, double interval,
                          std::size_t samples) {
  std::string out = Field("Channel code", channel.code);
  out += Field("Name of the channel", channel.name);
  out += Field("Test object number", "1");
  out += Field("Data source", "calculation");
  out += Field("Location", channel.code.substr(0, 12));
  out += Field("Dimension", channel.dimension);
  out += Field("Direction", std::string(1, channel.direction));
  out += Field("Unit", channel.unit);
  out += Field("Reference channel", "implicit");
  out += Field("Reference channel name", "NOVALUE");
  out += Field("Time of first sample", Number(first_time));
  out += Field("Sampling interval", Number(interval));
  out += Field("Number of samples", std::to_string(samples));
  out += Field("Channel frequency class", cfc > 0 ? std::to_string(cfc) : "NOVALUE");
  out += Field("Cut off frequency", "NOVALUE");
  out += Field("Reference system", channel.world_frame ? "global" : "local");
  return out;
}

// A time-history channel: column `column` of `series` (0 = the first after time) in SAE J211's
// axes (channel.sign), or the resultant of channel.components.
std::string SeriesChannel(const IsoMmeChannel& channel, int cfc, const TimeSeries& series,
                          std::size_t column, double interval) {
  const std::size_t rows = series.rows();
  auto value = [&](std::size_t row) {
    const double* at = series.values.data() + row * series.columns + 1;
    if (channel.components.empty()) return channel.sign * at[column];
    double sum = 0.0;
    for (const std::size_t c : channel.components) sum += at[c] * at[c];
    return std::sqrt(sum);
  };
  std::size_t high = 0, low = 0;
  for (std::size_t row = 1; row < rows; ++row) {
    if (value(row) > value(high)) high = row;
    if (value(row) < value(low)) low = row;
  }
  auto time = [&](std::size_t row) { return series.values[row * series.columns]; };
  std::string out = ChannelHeader(channel, cfc, rows > 0 ? time(0) : 0.0, interval, rows);
  if (rows > 0) {
    out += Field("First global maximum value", Number(value(high)));
    out += Field("Time of maximum value", Number(time(high)));
    out += Field("First global minimum value", Number(value(low)));
    out += Field("Time of minimum value", Number(time(low)));
  }
  out += Field("Data status", "ok");
  for (std::size_t row = 0; row < rows; ++row) out += Number(value(row)) + "\n";
  return out;
}

std::string CriterionChannel(const IsoMmeChannel& channel, const post::CriterionValue& value,
                             double interval) {
  std::string out = ChannelHeader(channel, value.filter_class,
                                  value.computed ? value.window_start : 0.0, interval, 1);
  if (value.computed) {
    out += Field("Comments", fmt::format("window {} s to {} s", Number(value.window_start),
                                         Number(value.window_end)));
  } else {
    out += Field("Comments", "not computed: " + value.reason);
  }
  if (value.incomplete) {
    out += Field("Comments", fmt::format("incomplete: the rows cover {} s to {} s of the run "
                                         "only; the value is over them",
                                         Number(value.seen_from), Number(value.seen_until)));
  }
  if (value.has_limit) {
    out +=
        Field("Comments", fmt::format("limit {} ({}): {}", Number(value.limit), value.limit_source,
                                      value.incomplete ? "not judged (incomplete)"
                                      : value.pass     ? "pass"
                                                       : "fail"));
  }
  out += Field("Data status", value.computed ? "ok" : "NOVALUE");
  out += (value.computed ? Number(value.value) : std::string("NOVALUE")) + "\n";
  return out;
}

}  // namespace

bool WriteIsoMme(const std::string& directory, const std::string& test, const Model& model,
                 const TimeSeries& raw, const TimeSeries& filtered,
                 const std::vector<post::CriterionValue>& criteria, std::string* error) {
  namespace fs = std::filesystem;
  const fs::path root(directory);
  std::error_code made;
  fs::create_directories(root / "Channel", made);
  if (made) {
    if (error)
      *error = fmt::format("cannot create `{}`: {}", (root / "Channel").string(), made.message());
    return false;
  }
  const IsoMmeCodes codes = MapIsoMmeCodes(model, raw, filtered, criteria);
  const double interval = post::SamplePeriod(model);

  // The test's header with ISO/TS 13499 (RED A 1.6) field names, as labs' tools read them.
  const std::string today = Today();
  std::string mme = Field("Data format edition number", "1.6");
  mme += Field("Laboratory name", "sled (simulation)");
  mme += Field("Laboratory test ref. number", test);
  mme += Field("Customer name", "NOVALUE");
  mme += Field("Customer test ref. number", "NOVALUE");
  mme += Field("Title", model.title.empty() ? std::string("NOVALUE") : model.title);
  mme += Field("Medium No./number of media", "1/1");
  mme += Field("Timestamp", today);
  mme += Field("Type of the test", "Simulation");
  mme += Field("Subtype of the test", "NOVALUE");
  mme += Field("Regulation", "NOVALUE");
  mme += Field("Date of the test", today);
  mme += Field("Number of test objects", "1");
  mme += Field("Name of test object 1", "vehicle 1 (the scene)");
  mme += Field("Comments",
               "computed by sled; SAE J211 axes (x forward, y right, z down); channel codes as "
               "sled's docs/outputs.md maps them");
  if (!WriteFile(root / (test + ".mme"), mme, error)) return false;

  const std::size_t total = codes.raw.size() + codes.filtered.size() + codes.criteria.size() +
                            codes.raw_resultants.size() + codes.filtered_resultants.size();
  std::string index = Field("Instrumentation standard", "SAEJ211");
  index += Field("Number of channels", std::to_string(total));
  std::size_t number = 0;
  auto write_channel = [&](const IsoMmeChannel& channel, const std::string& text) {
    ++number;
    index += Field(fmt::format("Name of channel {:03}", number),
                   fmt::format("{} / {}", channel.code, channel.name));
    return WriteFile(root / "Channel" / fmt::format("{}.{:03}", test, number), text, error);
  };
  for (std::size_t c = 0; c < codes.raw.size(); ++c) {
    if (!write_channel(codes.raw[c], SeriesChannel(codes.raw[c], 0, raw, c, interval))) {
      return false;
    }
  }
  auto class_of = [](const IsoMmeChannel& channel) {
    int cfc = 0;
    for (const int candidate : {1000, 600, 180, 60}) {
      if (FilterClassLetter(candidate) == channel.code[15]) cfc = candidate;
    }
    return cfc;
  };
  for (std::size_t c = 0; c < codes.filtered.size(); ++c) {
    const IsoMmeChannel& channel = codes.filtered[c];
    if (!write_channel(channel, SeriesChannel(channel, class_of(channel), filtered, c, interval))) {
      return false;
    }
  }
  for (const IsoMmeChannel& channel : codes.raw_resultants) {
    if (!write_channel(channel, SeriesChannel(channel, 0, raw, 0, interval))) return false;
  }
  for (const IsoMmeChannel& channel : codes.filtered_resultants) {
    if (!write_channel(channel, SeriesChannel(channel, class_of(channel), filtered, 0, interval))) {
      return false;
    }
  }
  for (std::size_t c = 0; c < codes.criteria.size(); ++c) {
    if (!write_channel(codes.criteria[c],
                       CriterionChannel(codes.criteria[c], criteria[c], interval))) {
      return false;
    }
  }
  return WriteFile(root / "Channel" / (test + ".chn"), index, error);
}

}  // namespace sled::runtime
