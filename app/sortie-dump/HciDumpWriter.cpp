#include "HciDumpWriter.h"

#include "HciMessageTypes.h"

#include <google/protobuf/message.h>
#include <google/protobuf/util/json_util.h>
#include <nlohmann/json.hpp>

namespace sortie::dump {
namespace {

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using json = nlohmann::ordered_json; // keys in the order written: offset first

bool isSecret(const FieldDescriptor *field)
{
    return field->cpp_type() == FieldDescriptor::CPPTYPE_STRING && (field->name() == "userPassword" || field->name() == "password");
}

// Replaces every set password field, at any depth, with "***". Visits only fields that are set.
void redact(Message &message)
{
    const auto *reflection = message.GetReflection();
    std::vector<const FieldDescriptor *> fields;
    reflection->ListFields(message, &fields);
    for (const auto *field : fields) {
        if (isSecret(field) && !field->is_repeated()) {
            reflection->SetString(&message, field, "***");
        } else if (field->cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE) {
            if (field->is_repeated()) {
                for (int i = 0; i < reflection->FieldSize(message, field); ++i)
                    redact(*reflection->MutableRepeatedMessage(&message, field, i));
            } else {
                redact(*reflection->MutableMessage(&message, field));
            }
        }
    }
}

json header(uint64_t offset, const hci::HciFrameHeader &h)
{
    json line = {{"offset", offset}, {"instanceId", h.instanceId}, {"type", h.type}};
    const auto name = hci::HciMessageTypes::name(h.type);
    line["message"] = name.empty() ? json(nullptr) : json(std::string(name));
    return line;
}

} // namespace

HciDumpWriter::HciDumpWriter(std::ostream &out)
    : HciDumpWriter(out, Options{})
{
}

HciDumpWriter::HciDumpWriter(std::ostream &out, Options options)
    : m_out(out)
    , m_options(options)
{
}

void HciDumpWriter::feed(std::string_view bytes)
{
    m_decoder.feed(bytes);
    drain();
}

void HciDumpWriter::drain()
{
    while (auto result = m_decoder.next()) {
        if (auto *frame = std::get_if<hci::HciFrame>(&*result))
            writeFrame(*frame);
        else
            writeDropped(std::get<hci::HciDroppedFrame>(*result));
    }
}

void HciDumpWriter::writeFrame(hci::HciFrame &frame)
{
    if (!m_options.revealSecrets)
        redact(*frame.message);
    std::string body;
    google::protobuf::util::JsonPrintOptions options;
    options.preserve_proto_field_names = false; // lowerCamelCase json_name, as UgCS's own JSON does
    if (!google::protobuf::util::MessageToJsonString(*frame.message, &body, options).ok())
        body = "null";
    std::string line = header(frame.offset, frame.header).dump();
    line.pop_back(); // splice the protobuf JSON in as it is, without re-parsing it
    m_out << line << ",\"json\":" << body << "}\n";
    m_decoder.recycle(std::move(frame.message));
}

void HciDumpWriter::writeDropped(const hci::HciDroppedFrame &dropped)
{
    json line = header(dropped.offset, dropped.header);
    line["dropped"] = hci::toString(dropped.reason);
    line["detail"] = dropped.detail;
    if (dropped.bytesDiscarded)
        line["bytesDiscarded"] = dropped.bytesDiscarded;
    m_out << line.dump() << '\n';
}

void HciDumpWriter::finish()
{
    drain();
    const size_t left = m_decoder.buffered();
    if (left == 0)
        return;
    json line;
    if (left >= hci::kHciHeaderSize) {
        // A header arrived but not all of its payload.
        const auto h = hci::HciFrameHeader::read(m_decoder.pending().data());
        line = header(m_decoder.streamOffset(), h);
        line["dropped"] = "truncated";
        line["detail"] = "the stream ends " + std::to_string(left - hci::kHciHeaderSize) + " bytes into a payload of "
            + std::to_string(h.length);
    } else {
        line = {{"offset", m_decoder.streamOffset()}, {"dropped", "truncated"}};
        line["detail"] = "the stream ends with " + std::to_string(left) + " bytes, less than a frame header";
    }
    ++m_truncated;
    m_out << line.dump() << '\n';
}

} // namespace sortie::dump
