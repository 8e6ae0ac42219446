#pragma once

#include <QString>

namespace sortie::files {

// Routes, flight logs and map packs are the operator's: another local user reads none of them.
// The folders Sortie makes for them are 0700 and the files 0600, whatever the umask. A folder
// that exists already is left as it is (it may be one the operator chose, such as their home).

// Makes `path` and any missing folder above it, each new one 0700. False, with why in *error,
// when it cannot.
bool makePrivatePath(const QString &path, QString *error = nullptr);

// Creates `path` empty with 0600 when it does not exist yet (a file SQLite opens afterwards keeps
// its mode, and gives it to its -wal and -shm). False, with why in *error, when it cannot.
bool createPrivateFile(const QString &path, QString *error = nullptr);

// Creates `path` as a new file, 0600, only if it does not exist (O_EXCL): the claim of a name that
// two processes may pick at once. False when it exists or cannot be made.
bool claimNewFile(const QString &path);

// A folder for a run that keeps nothing of the operator's (the demo): <XDG_RUNTIME_DIR>/<name>
// when XDG_RUNTIME_DIR is this user's own private folder, else a new <temp>/<name>-XXXXXX made by
// mkdtemp (0700). Never a fixed name in a shared folder, which another user could make first.
// Empty, with why in *error, when neither can be made.
QString privateRuntimeFolder(const QString &name, QString *error = nullptr);

} // namespace sortie::files
