#include "HciObjectType.h"

#include "Domain.pb.h"

#include <array>

namespace sortie::hci {
namespace {

using google::protobuf::FieldDescriptor;

constexpr std::array kNames = {"Vehicle", "Route", "Mission", "VehicleProfile", "User", "TraverseAlgorithm", "CommandDefinition", "RoutePass", "NoFlightZone"};

const FieldDescriptor *wrapperFieldFor(const google::protobuf::Descriptor *type)
{
    const auto *wrapper = pb::DomainObjectWrapper::descriptor();
    for (int i = 0; i < wrapper->field_count(); ++i)
        if (wrapper->field(i)->message_type() == type)
            return wrapper->field(i);
    return nullptr;
}

} // namespace

QString objectTypeName(HciObjectType type)
{
    return QString::fromLatin1(kNames.at(size_t(type)));
}

std::optional<HciObjectType> objectTypeFromName(const QString &name)
{
    for (size_t i = 0; i < kNames.size(); ++i)
        if (name == QLatin1String(kNames[i]))
            return HciObjectType(i);
    return std::nullopt;
}

bool isObjectType(const QString &name)
{
    const auto *type = google::protobuf::DescriptorPool::generated_pool()->FindMessageTypeByName(
        "com.ugcs.ucs.proto." + name.toStdString());
    return type && wrapperFieldFor(type);
}

bool wrapObject(const google::protobuf::Message &object, pb::DomainObjectWrapper *wrapper)
{
    const auto *field = wrapperFieldFor(object.GetDescriptor());
    if (!field)
        return false;
    wrapper->Clear();
    wrapper->GetReflection()->MutableMessage(wrapper, field)->CopyFrom(object);
    return true;
}

const google::protobuf::Message *unwrapObject(const pb::DomainObjectWrapper &wrapper)
{
    const auto *reflection = wrapper.GetReflection();
    const auto *descriptor = wrapper.GetDescriptor();
    for (int i = 0; i < descriptor->field_count(); ++i)
        if (reflection->HasField(wrapper, descriptor->field(i)))
            return &reflection->GetMessage(wrapper, descriptor->field(i));
    return nullptr;
}

const google::protobuf::Message *unwrapObject(const pb::DomainObjectWrapper &wrapper, const QString &objectType)
{
    const auto *type = google::protobuf::DescriptorPool::generated_pool()->FindMessageTypeByName(
        "com.ugcs.ucs.proto." + objectType.toStdString());
    const auto *field = type ? wrapperFieldFor(type) : nullptr;
    if (!field || !wrapper.GetReflection()->HasField(wrapper, field))
        return nullptr;
    return &wrapper.GetReflection()->GetMessage(wrapper, field);
}

int objectId(const google::protobuf::Message &object)
{
    const auto *field = object.GetDescriptor()->FindFieldByName("id");
    if (!field || field->cpp_type() != FieldDescriptor::CPPTYPE_INT32 || field->is_repeated()
        || !object.GetReflection()->HasField(object, field))
        return -1;
    return object.GetReflection()->GetInt32(object, field);
}

} // namespace sortie::hci
