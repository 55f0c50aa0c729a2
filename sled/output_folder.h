// The folder `sled run` writes, as a RunSink: timeseries.csv, timeseries_filtered.csv (when any
// group has a filter class), summary.json, animation.glb, with `iso_mme` the ISO-MME data set in
// DIR/iso-mme, and at every stop time of the run the complete state in DIR/dump_<T>.txt
// (docs/outputs.md).
#pragma once

#include <functional>
#include <future>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "output/export/animation_recorder.h"
#include "sled/simulate.h"

namespace sled {

struct OutputFolderOptions {
  std::string directory;           // an existing folder
  std::string test_name = "sled";  // the ISO-MME test name
  bool iso_mme = false;            // also write the ISO-MME data set into DIR/iso-mme
  // Listed first among summary.json's warnings: the compile's notes (Compilation::Notes).
  std::vector<std::string> notes;
  // For an interrupted run, the signal's name for summary.json ("SIGINT"); may be empty.
  std::function<std::string()> interrupted_by;
  // Make timeseries.csv's lines as the rows come and write it on a thread of its own from
  // OnRows, while the post-processing and the other files go on, each CSV formatted on two
  // threads (`sled run`; the files are the same).
  bool parallel_writes = false;
};

class OutputFolder : public RunSink {
 public:
  OutputFolder(const runtime::Model& model, OutputFolderOptions options);

  // An animation frame.
  void OnRow(const runtime::Model& model, const runtime::Data& data) override;
  // The state printout DIR/dump_<T>.txt.
  void OnStop(const runtime::Model& model, const runtime::Data& data) override;
  // With parallel_writes: timeseries.csv's lines, made as the rows come (on the rows' thread).
  void OnRowValues(std::span<const double> row) override;
  // With parallel_writes: starts writing timeseries.csv.
  void OnRows(const runtime::Model& model, const runtime::TimeSeries& series) override;
  // Every file of the folder, each tried; false with `error` naming every file that could not be
  // written and why, one line each. summary.json lists those written before it that failed.
  bool OnEnd(const runtime::Model& model, const RunResult& result, std::string* error) override;
  // The names of the files (and `iso-mme/`) OnEnd wrote.
  const std::set<std::string>& written() const { return written_; }

  // The state printouts written, and why others could not be.
  const std::vector<std::string>& dumps_written() const { return dumps_written_; }
  const std::vector<std::string>& dump_errors() const { return dump_errors_; }

 private:
  OutputFolderOptions options_;
  runtime::AnimationRecorder animation_;
  std::vector<std::string> dumps_written_;
  std::vector<std::string> dump_errors_;
  std::set<std::string> written_;
  // The lines of the rows OnRowValues saw, and how many.
  std::string row_lines_;
  std::size_t rows_seen_ = 0;
  // timeseries.csv being written (OnRows): whether it was, and why not.
  std::future<std::pair<bool, std::string>> series_written_;
};

}  // namespace sled
