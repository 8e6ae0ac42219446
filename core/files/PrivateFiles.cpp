#include "PrivateFiles.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sortie::files {

namespace {

void setError(QString *error, const QString &message)
{
    if (error)
        *error = message;
}

// A folder only this user owns and reaches: not a link, owned by us, no group or other bits.
bool isOwnPrivateFolder(const QByteArray &path)
{
    struct stat st{};
    return ::lstat(path.constData(), &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == ::getuid() && (st.st_mode & 077) == 0;
}

} // namespace

bool makePrivatePath(const QString &path, QString *error)
{
    const QString absolute = QDir::cleanPath(QFileInfo(path).absoluteFilePath());
    QStringList missing;
    QString existing = absolute;
    while (!QFileInfo(existing).exists()) {
        missing.prepend(existing);
        const QString parent = QFileInfo(existing).path();
        if (parent == existing)
            break;
        existing = parent;
    }
    if (!QFileInfo(existing).isDir()) {
        setError(error, QCoreApplication::translate("PrivateFiles", "Cannot create the folder %1: %2 is not a folder").arg(absolute, existing));
        return false;
    }
    for (const QString &folder : std::as_const(missing)) {
        const QByteArray name = QFile::encodeName(folder);
        // mkdir applies the umask, which can only take bits away from 0700.
        if (::mkdir(name.constData(), 0700) != 0 && errno != EEXIST) {
            setError(error, QCoreApplication::translate("PrivateFiles", "Cannot create the folder %1: %2").arg(folder, QString::fromLocal8Bit(std::strerror(errno))));
            return false;
        }
    }
    if (!QFileInfo(absolute).isDir()) {
        setError(error, QCoreApplication::translate("PrivateFiles", "Cannot create the folder %1").arg(absolute));
        return false;
    }
    return true;
}

bool createPrivateFile(const QString &path, QString *error)
{
    const QByteArray name = QFile::encodeName(path);
    const int fd = ::open(name.constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd >= 0) {
        ::close(fd);
        return true;
    }
    if (errno == EEXIST)
        return true;
    setError(error, QCoreApplication::translate("PrivateFiles", "Cannot create %1: %2").arg(path, QString::fromLocal8Bit(std::strerror(errno))));
    return false;
}

bool claimNewFile(const QString &path)
{
    const QByteArray name = QFile::encodeName(path);
    const int fd = ::open(name.constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0)
        return false;
    ::close(fd);
    return true;
}

QString privateRuntimeFolder(const QString &name, QString *error)
{
    const QString runtime = qEnvironmentVariable("XDG_RUNTIME_DIR");
    if (!runtime.isEmpty() && isOwnPrivateFolder(QFile::encodeName(runtime))) {
        const QString folder = QDir(runtime).filePath(name);
        const QByteArray encoded = QFile::encodeName(folder);
        if ((::mkdir(encoded.constData(), 0700) == 0 || errno == EEXIST) && isOwnPrivateFolder(encoded))
            return folder;
    }
    QByteArray pattern = QFile::encodeName(QDir::temp().filePath(name + QStringLiteral("-XXXXXX")));
    if (::mkdtemp(pattern.data()))
        return QFile::decodeName(pattern);
    setError(error, QCoreApplication::translate("PrivateFiles", "Cannot create a private folder in %1: %2").arg(QDir::tempPath(), QString::fromLocal8Bit(std::strerror(errno))));
    return {};
}

} // namespace sortie::files
