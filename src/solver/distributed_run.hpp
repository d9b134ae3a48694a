#pragma once
// What a run over several MPI ranks supports (issue 17): the explicit forming run with its
// frames, history and summary, and an implicit springback after it (on rank 0). The features
// below need data a rank does not keep, and are refused before any work with a message naming
// the case key.
#include <string>

#include "model/model.hpp"

namespace sf {

/// Throws InputError naming `case_file` and the key when the model uses a feature that a run
/// over `ranks` > 1 MPI ranks does not support: a static analysis, mass scaling, pressure loads
/// (they follow the deforming surface of elements another rank computes) and springback by
/// dynamic relaxation. Does nothing for ranks == 1.
void check_distributable(const Model& model, const std::string& case_file, int ranks);

}  // namespace sf
