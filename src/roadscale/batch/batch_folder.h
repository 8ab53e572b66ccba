#pragma once

#include <string>
#include <vector>

namespace roadscale::batch {

// A batch's output folder DIR holds one folder per drive (DIR/<name>/, run's outputs, the
// drive's log and record), the summary files, slurm/ with the Slurm scripts, and
// DIR/batch.json: the drives' names in the manifest's order, so that `--summarize DIR` lists
// them as the batch did.
std::string DriveFolder(const std::string& dir, const std::string& name);

// Writes DIR/batch.json (creating DIR). Throws Error naming what cannot be written.
void WriteDriveList(const std::string& dir, const std::vector<std::string>& names);

// The drives of the batch in DIR: DIR/batch.json's list, else every subfolder holding a
// drive record whose name a drive can have (CheckDriveName), sorted by name. Throws Error when
// DIR is not a folder or batch.json is broken or holds a name no drive can have.
std::vector<std::string> DriveNamesIn(const std::string& dir);

}  // namespace roadscale::batch
