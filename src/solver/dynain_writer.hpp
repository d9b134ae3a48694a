#pragma once
// The formed part as an LS-DYNA keyword file (a "dynain" file) for the crash engineer (issue 32,
// item 5; docs/process-chain.md): *NODE (current coordinates), *ELEMENT_SHELL_THICKNESS (the
// element's current thickness at its corners), *INITIAL_STRESS_SHELL (at every
// through-thickness point: its position, the stress in global components and the equivalent
// plastic strain) and *INITIAL_STRAIN_SHELL (the logarithmic strains of the bottom and top
// surfaces, element/shell_surface_strain.hpp), in the fixed-width fields of the LS-DYNA keyword
// manual (LARGE = 0). Node and element numbers are the part's indices plus one; the part id is 1,
// or for a blank of several parts each part's index plus one, named in the header comment (the
// crash deck's *PART cards give them sections and materials). Units are the part's (mm, tonne, s;
// N, MPa), said in the file's header comment.
#include <filesystem>
#include <string>

#include "solver/formed_part.hpp"

namespace sf {

/// Writes `part` to `file` (replaced). Throws OutputError naming the file when it cannot be
/// written, InputError when the part holds a value that is not finite.
void write_dynain(const FormedPart& part, const std::filesystem::path& file);

/// `value` in `width` characters, right-aligned after at least one blank: of the fixed and
/// exponent forms that fit, the one read back closest to the value (a stress of -123.456789 MPa
/// keeps 7 digits in 10 columns: " -123.4568"). Throws InputError for a value that is not finite.
std::string keyword_real(double value, int width);

}  // namespace sf
