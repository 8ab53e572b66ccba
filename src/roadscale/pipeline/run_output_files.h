#pragma once

#include <fstream>
#include <string>

#include "roadscale/geometry/rigid3.h"
#include "roadscale/pipeline/sequential_pipeline.h"

namespace roadscale {

// The files of one run in its output folder, one row per frame each: OUT/poses_kitti.txt
// (world_from_cam), OUT/poses_tum.txt (the same with the timestamp) and OUT/frames.csv (the
// frame's record). Fed by the pipeline's FrameOutput; every row is flushed as it is written,
// so that whatever stops the run leaves the rows before it intact.
class RunOutputFiles {
 public:
  // Creates `out_dir` when needed and the three files, emptied; frames.csv starts with its
  // header, FrameRecordCsvHeader() and then `diagnostics_header` (the scale source's or the
  // keyframe back end's columns: SequentialPipeline::DiagnosticsCsvHeader). Throws Error
  // naming the folder or file that cannot be created.
  RunOutputFiles(const std::string& out_dir, const std::string& diagnostics_header);

  // Appends the frame's rows. A record without diagnostics (a frame the scale source did not
  // see) gets empty diagnostics columns. Throws Error naming the file when a write fails.
  void Write(const FrameRecord& record, const Rigid3d& world_from_cam);

 private:
  std::string diagnostics_header_;
  std::string poses_path_;
  std::string tum_path_;
  std::string records_path_;
  std::ofstream poses_;
  std::ofstream tum_;
  std::ofstream records_;
};

}  // namespace roadscale
