// ubii::Value and the record type table: every member of the schema, the quirk of two members of
// one type, typed access and its errors, and that the table covers the .proto's whole oneof.
#include <set>

#include <gtest/gtest.h>

#include "ubii/ubii.hpp"

namespace
{

TEST(Value, ConvertsFromEachTypeToTheMemberThatHoldsIt)
{
    EXPECT_EQ(ubii::Value(2.5).type(), ubii::RecordType::DOUBLE);
    EXPECT_EQ(ubii::Value(2.5f).type(), ubii::RecordType::FLOAT);
    EXPECT_EQ(ubii::Value(std::int32_t{7}).type(), ubii::RecordType::INT32);
    EXPECT_EQ(ubii::Value(true).type(), ubii::RecordType::BOOL);
    EXPECT_EQ(ubii::Value("text").type(), ubii::RecordType::STRING);
    EXPECT_EQ(ubii::Value(std::string_view("text")).type(), ubii::RecordType::STRING);
    EXPECT_EQ(ubii::Value(ubii::vector3(1, 2, 3)).type(), ubii::RecordType::VECTOR3);
    EXPECT_EQ(ubii::Value(ubii::Object2DList()).type(), ubii::RecordType::OBJECT2D_LIST);
    EXPECT_EQ(ubii::Value(ubii::Session()).type(), ubii::RecordType::SESSION);
    EXPECT_TRUE(ubii::Value().empty());
    EXPECT_EQ(ubii::Value().type(), ubii::RecordType::NONE);
}

TEST(Value, TwoMembersOfOneTypeStayApart)
{
    const ubii::Quaternion q = ubii::quaternion(0, 0, 0, 1);
    const ubii::Value plain(q);
    const ubii::Value quirk(ubii::RecordType::QUATERNION_LIST, q);
    EXPECT_EQ(plain.type(), ubii::RecordType::QUATERNION);
    EXPECT_EQ(quirk.type(), ubii::RecordType::QUATERNION_LIST);
    EXPECT_EQ(quirk.as<ubii::Quaternion>().w(), 1.0);
    EXPECT_TRUE(quirk.holds<ubii::Quaternion>());
}

TEST(Value, TypedAccessToAnotherTypeIsAWrongTypeNamingBoth)
{
    const ubii::Value value(2.5);
    EXPECT_EQ(value.as<double>(), 2.5);
    EXPECT_EQ(value.get_if<ubii::Vector3>(), nullptr);
    try {
        (void)value.as<ubii::Vector3>();
        ADD_FAILURE() << "a double read as a Vector3";
    } catch (const ubii::WrongType &error) {
        EXPECT_EQ(error.status(), ubii::Status::wrong_type);
        EXPECT_STREQ(error.what(),
                     "the value holds double (double), not vector3 (ubii.dataStructure.Vector3)");
    }
    EXPECT_THROW(ubii::Value(ubii::RecordType::VECTOR3, 1.0), ubii::WrongType);
}

// The table is generated from the schema; protobuf's descriptor of the same .proto files is the
// independent witness that no member is missing or mistyped.
TEST(RecordTypes, TheTableCoversEveryMemberOfTheRecordOneof)
{
    const auto *record = ubii::TopicDataRecord::descriptor();
    const auto *oneof = record->FindOneofByName("type");
    ASSERT_NE(oneof, nullptr);
    std::set<int> numbers;
    for (int i = 0; i < oneof->field_count(); ++i)
        numbers.insert(oneof->field(i)->number());
    std::set<int> table;
    for (ubii::RecordType type : ubii::detail::record_types) {
        if (type == ubii::RecordType::NONE)
            continue;
        table.insert(static_cast<int>(type));
        const auto *field = record->FindFieldByNumber(static_cast<int>(type));
        ASSERT_NE(field, nullptr) << static_cast<int>(type);
        EXPECT_EQ(ubii::record_type_name(type), field->name());
        const std::string format = field->message_type() != nullptr
                                       ? field->message_type()->full_name()
                                       : std::string(field->type_name());
        EXPECT_EQ(ubii::message_format(type), format);
        const ubii::RecordType back = ubii::record_type_for_format(format);
        EXPECT_EQ(ubii::message_format(back), format);
        EXPECT_LE(static_cast<int>(back), static_cast<int>(type));
    }
    EXPECT_EQ(table, numbers);
    EXPECT_EQ(ubii::record_type_for_format("ubii.noSuch.Thing"), ubii::RecordType::NONE);
}

// Each message member's C++ alternative is the class protobuf generated for its type.
template <class T> std::string cpp_format()
{
    if constexpr (std::is_base_of_v<google::protobuf::Message, T>)
        return T::descriptor()->full_name();
    else
        return "";
}

TEST(RecordTypes, EachAlternativeIsTheMembersGeneratedClass)
{
#define UBII_TEST_ALTERNATIVE(upper, number, member, format, cpp_type)                             \
    if (!cpp_format<cpp_type>().empty()) {                                                         \
        EXPECT_EQ(cpp_format<cpp_type>(), format) << member;                                       \
    }
    UBII_RECORD_MEMBER_LIST(UBII_TEST_ALTERNATIVE)
#undef UBII_TEST_ALTERNATIVE
}

TEST(Record, OwnsWhatItIsBuiltFromAndCopiesKeepIt)
{
    ubii::Record record("/hand", ubii::vector3(1, 2, 3));
    EXPECT_FALSE(record.lent());
    ubii::Record copy = record;
    record.set_topic("/elsewhere");
    record.set_value(4.0);
    EXPECT_EQ(copy.topic(), "/hand");
    EXPECT_EQ(copy.as<ubii::Vector3>().z(), 3.0);
    ubii::Record moved = std::move(copy);
    EXPECT_EQ(moved.topic(), "/hand"); // the view follows the moved storage
    EXPECT_EQ(record.as<double>(), 4.0);
    EXPECT_THROW(record.image(), ubii::WrongType);
}

} // namespace
