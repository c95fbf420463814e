#pragma once
// A steady-curving sweep (curving/steady_curving.hpp) as files and a summary:
//   <stem>_curving.csv   one row per steady state: the condition (cant
//                        deficiency, speed, radius, cant, lateral
//                        acceleration) and per wheelset its lateral shift,
//                        angle of attack, roll, Sum Y against Prud'homme,
//                        and per wheel Y, Q, Y/Q against Nadal and whether
//                        it is on its flange;
//   <stem>_curving.json  the same, with the scene's conditions, how each
//                        state was found, and where the vehicle has no
//                        steady state physically, the statement.
// Results flow one way: the sweep is computed first, then written.
#include <railstab/curving/steady_curving.hpp>
#include <railstab/io/output_set.hpp>

#include <string>

namespace railstab {

// Stages both files in `outputs` (the caller commits) and returns the
// summary for the terminal.
std::string write_curving_results(const Model& scene_model, const CurvingSweep& sweep,
                                  CurvingSweepKind kind, OutputSet& outputs,
                                  const std::string& stem);

}  // namespace railstab
