#ifndef UBII_VALUE_HPP
#define UBII_VALUE_HPP

// ubii::Value: the value of a TopicDataRecord, one alternative per member of the schema (generated
// from it, see record_type.hpp), or none. Two members of the same C++ type stay apart: the Value
// knows which member it is, not only which type.
//
//     ubii::Value v = ubii::vector3(1, 2, 3);   // VECTOR3
//     v.type();                                 // RecordType::VECTOR3
//     v.as<ubii::Vector3>().x();                // 1; ubii::WrongType for any other type
//     ubii::Value d = 2.5;                      // DOUBLE; int32_t, float, bool, std::string alike

#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "ubii/error.hpp"
#include "ubii/record_type.hpp"

namespace ubii
{

class Value
{
  public:
    using Variant = std::variant<std::monostate
#define UBII_CPP_VALUE_ALTERNATIVE(upper, number, name, format, cpp_type) , cpp_type
                                     UBII_RECORD_MEMBER_LIST(UBII_CPP_VALUE_ALTERNATIVE)
#undef UBII_CPP_VALUE_ALTERNATIVE
                                 >;

    Value() = default;
    // The member record_type_of<T> names.
    template <class T, class D = std::decay_t<T>,
              class = std::enable_if_t<is_record_value_v<D>>>
    Value(T &&value) // NOLINT(google-explicit-constructor): a value converts like the member it is
    {
        variant_.template emplace<detail::alternative_of(record_type_of<D>)>(
            std::forward<T>(value));
    }
    Value(const char *text) : Value(std::string(text))
    {
    }
    Value(std::string_view text) : Value(std::string(text))
    {
    }
    // A member named explicitly; ubii::WrongType if `type` does not hold a T.
    template <class T> Value(RecordType type, T &&value)
    {
        emplace(type, std::forward<T>(value));
    }

    RecordType type() const noexcept
    {
        return detail::record_types[variant_.index()];
    }
    bool empty() const noexcept
    {
        return variant_.index() == 0;
    }
    // Whether the member held is of C++ type T.
    template <class T> bool holds() const noexcept
    {
        return get_if<T>() != nullptr;
    }
    template <class T> const T *get_if() const noexcept
    {
        return std::visit(
            [](const auto &held) -> const T * {
                if constexpr (std::is_same_v<std::decay_t<decltype(held)>, T>)
                    return &held;
                else
                    return nullptr;
            },
            variant_);
    }
    template <class T> T *get_if() noexcept
    {
        return const_cast<T *>(std::as_const(*this).template get_if<T>());
    }
    // The held member as a T; ubii::WrongType naming both types if it is another.
    template <class T> const T &as() const
    {
        if (const T *held = get_if<T>())
            return *held;
        throw_wrong_type(record_type_of<T>);
    }
    template <class T> T &as()
    {
        return const_cast<T &>(std::as_const(*this).template as<T>());
    }
    const Variant &variant() const noexcept
    {
        return variant_;
    }
    template <class Visitor> decltype(auto) visit(Visitor &&visitor) const
    {
        return std::visit(std::forward<Visitor>(visitor), variant_);
    }

  private:
    template <class T> void emplace(RecordType type, T &&value)
    {
        using D = std::decay_t<T>;
        switch (type) {
#define UBII_CPP_VALUE_EMPLACE(upper, number, name, format, cpp_type)                              \
    case RecordType::upper:                                                                        \
        if constexpr (std::is_constructible_v<cpp_type, T &&>) {                                   \
            variant_.template emplace<detail::alternative_of(RecordType::upper)>(                  \
                std::forward<T>(value));                                                           \
            return;                                                                                \
        }                                                                                          \
        break;
            UBII_RECORD_MEMBER_LIST(UBII_CPP_VALUE_EMPLACE)
#undef UBII_CPP_VALUE_EMPLACE
        case RecordType::NONE:
            break;
        }
        throw_mismatch(type, record_type_of<D>);
    }
    [[noreturn]] void throw_wrong_type(RecordType wanted) const;
    [[noreturn]] static void throw_mismatch(RecordType member, RecordType given);

    Variant variant_;
};

} // namespace ubii

#endif
