#include "SimStoreFile.h"

#include "HciObjectType.h"
#include "Messages.pb.h"
#include "SimObjectStore.h"

#include <google/protobuf/util/json_util.h>
#include <nlohmann/json.hpp>

#include <QFile>
#include <QSaveFile>

namespace sortie::sim {
namespace {

using json = nlohmann::json;
constexpr const char *kFormat = "sortie-sim-store";

bool failWith(QString *error, const QString &path, const QString &message)
{
    if (error)
        *error = path + QStringLiteral(": ") + message;
    return false;
}

} // namespace

bool SimStoreFile::load(const QString &path, SimObjectStore &store, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return failWith(error, path, file.errorString());
    const QByteArray bytes = file.readAll();
    json doc;
    try {
        doc = json::parse(bytes.constBegin(), bytes.constEnd());
    } catch (const json::parse_error &e) {
        return failWith(error, path, QStringLiteral("not valid JSON (%1)").arg(QString::fromUtf8(e.what())));
    }
    if (!doc.is_object() || doc.value("format", "") != kFormat)
        return failWith(error, path, QStringLiteral("format: expected \"%1\"").arg(QLatin1String(kFormat)));
    if (!doc.contains("objects") || !doc["objects"].is_array())
        return failWith(error, path, QStringLiteral("objects: expected an array"));

    const json &objects = doc["objects"];
    for (size_t i = 0; i < objects.size(); ++i) {
        const QString where = QStringLiteral("objects[%1]").arg(i);
        const json &entry = objects[i];
        if (!entry.is_object() || !entry.contains("type") || !entry["type"].is_string())
            return failWith(error, path, where + QStringLiteral(".type: expected a string"));
        const QString type = QString::fromStdString(entry["type"].get<std::string>());
        if (!entry.contains("object") || !entry["object"].is_object())
            return failWith(error, path, where + QStringLiteral(".object: expected an object"));
        pb::DomainObjectWrapper wrapper;
        const auto status = google::protobuf::util::JsonStringToMessage(entry["object"].dump(), &wrapper);
        if (!status.ok())
            return failWith(error, path, where + QStringLiteral(".object: ") + QString::fromStdString(status.ToString()));
        const auto *object = hci::unwrapObject(wrapper, type);
        if (!object)
            return failWith(error, path, where + QStringLiteral(".object: holds no %1").arg(type));
        if (hci::objectId(*object) < 0)
            return failWith(error, path, where + QStringLiteral(".object: the %1 has no id").arg(type));
        store.insert(type, wrapper);
    }
    if (doc.contains("nextId")) {
        if (!doc["nextId"].is_number_integer())
            return failWith(error, path, QStringLiteral("nextId: expected an integer"));
        store.setNextId(std::max(store.nextId(), doc["nextId"].get<int>()));
    }
    return true;
}

bool SimStoreFile::save(const QString &path, const SimObjectStore &store, QString *error)
{
    json doc = {{"format", kFormat}, {"version", 1}, {"nextId", store.nextId()}, {"objects", json::array()}};
    google::protobuf::util::JsonPrintOptions options;
    options.preserve_proto_field_names = false;
    for (const QString &type : store.types()) {
        for (const auto *wrapper : store.list(type)) {
            std::string text;
            if (!google::protobuf::util::MessageToJsonString(*wrapper, &text, options).ok())
                return failWith(error, path, QStringLiteral("cannot write a %1 as JSON").arg(type));
            doc["objects"].push_back({{"type", type.toStdString()}, {"object", json::parse(text)}});
        }
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return failWith(error, path, file.errorString());
    const std::string text = doc.dump(1);
    file.write(text.data(), qint64(text.size()));
    if (!file.commit())
        return failWith(error, path, file.errorString());
    return true;
}

} // namespace sortie::sim
