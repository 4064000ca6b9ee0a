// SPDX-License-Identifier: GPL-2.0-or-later
// gen_doc.hpp - the man page (groff -man, section 9) of a component, in the layout
// of the reference pages: NAME, SYNOPSIS, DESCRIPTION, FUNCTIONS, PINS, PARAMETERS,
// NOTES, SEE ALSO, AUTHOR, LICENSE.
#pragma once

#include <string>

#include "model.hpp"

namespace hal::comp {

// 'date' goes into the .TH line (e.g. "2011-08-27").
std::string generate_doc(const Component& c, const std::string& date);

// "loadrt NAME [count=N|names=...]" (or "loadusr NAME") as plain text, for tests and SYNOPSIS.
std::string synopsis_text(const Component& c);

}  // namespace hal::comp
