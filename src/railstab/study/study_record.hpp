#pragma once
// The study record (<stem>_study_record.toml): a study's definition, which
// shard of it a run computed, and its points with every number exact
// (TOML floats are written with 17 significant digits and read back with
// strtod, so a double makes the round trip unchanged). `railstab merge`
// joins the records of the shards into the points of the whole study.
#include <railstab/study/study_run.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railstab {

void write_study_record(std::ostream& out, const StudyDefinition& definition,
                        const StudyShard& shard, const std::vector<StudyPoint>& points);

struct StudyRecord {
  std::string path;
  StudyDefinition definition;
  StudyShard shard;
  std::vector<StudyPoint> points;
};

// Throws std::runtime_error "<path>: <key>: expected ..., got ..." for a
// file that is not a study record or is damaged, and "<path>: <key>: renamed
// to <new key>; ..." for a record written with the old key names (format
// "railstab study record 1").
StudyRecord read_study_record(const std::string& path);

// The points of the whole study from the records of its shards. Throws
// std::runtime_error naming the records when they come from different
// studies (definition, scene file bytes, shard count), a shard is given
// twice, a shard is missing, or a record lacks points its shard holds.
std::vector<StudyPoint> merge_study_records(const std::vector<StudyRecord>& records);

}  // namespace railstab
