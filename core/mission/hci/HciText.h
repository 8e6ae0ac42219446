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

// Whether a value changed, counting NaN as equal to NaN: a server's NaN left alone stays its NaN.
inline bool differs(double a, double b) { return !(a == b || (a != a && b != b)); }

} // namespace sortie::mission
