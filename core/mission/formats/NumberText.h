#pragma once

#include <QByteArray>
#include <QString>

#include <optional>

namespace sortie::mission::formats {

// The shortest decimal text that reads back as exactly the same double ("47.63311996", "5").
QByteArray shortestNumber(double v);
// Parses a whole field as a finite double in the C locale; nullopt otherwise.
std::optional<double> parseNumber(QByteArrayView text);

} // namespace sortie::mission::formats
