#pragma once

#include <QString>

#include <optional>
#include <string>

namespace sortie::mission {

// Segment parameters travel as strings. The UgCS server and SDK are Java, so numbers are written
// the way Java's Double.toString writes them ("5.0", "7.5", "1.0E-4", "1.25E7") and read in any
// decimal form.
std::string javaDoubleString(double v);
std::optional<double> parseHciDouble(const std::string &text);

} // namespace sortie::mission
