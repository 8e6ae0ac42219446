#pragma once

#include <QByteArray>
#include <QString>

namespace sortie::client {

// Replaces `path` with `data` so that a crash at any moment leaves either the old file or the new
// one, whole: write to a temporary file beside it, flush and fsync it (QSaveFile::commit does both
// since Qt 5.1), rename it over the old one, then fsync the directory so the rename itself is on
// disk. The file is 0600 (the operator's alone), whatever the umask. Returns an empty string on
// success, else what went wrong, naming the file.
QString writeFileAtomically(const QString &path, const QByteArray &data);

} // namespace sortie::client
