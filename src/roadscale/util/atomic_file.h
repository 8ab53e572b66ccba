#pragma once

#include <string>

namespace roadscale {

// Writes `text` as the whole of the file at `path`, through a temporary file beside it that is
// synced and then renamed over `path`: a reader, a crash or a full disk sees the previous file
// or the new one, never a file cut mid-row (a full disk left gt_poses_kitti.txt cut and
// metrics.json empty; issue 30). The temporary file (".NAME.tmpPID", hidden, so that no drive
// name or glob takes it) is removed when anything fails. Throws Error naming `path` and the
// reason.
void WriteFileAtomically(const std::string& path, const std::string& text);

}  // namespace roadscale
