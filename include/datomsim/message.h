// Typed messages between module programs, carried by value without allocation (public API).
//
// A message type is a small trivially copyable struct with a name:
//
//   struct DistanceMsg {
//     static constexpr std::string_view kName = "DistanceMsg";
//     Cell cell;
//     int32_t distance;
//   };
//
// Message::of(DistanceMsg{...}) wraps it; the receiver asks `message.as<DistanceMsg>()`, which is
// null for any other type. No integer codes and no casts in programs.
#pragma once

#include <array>
#include <cstring>
#include <string_view>
#include <type_traits>

namespace datomsim {

class Message;

namespace detail {
// How the simulator keeps a message in flight in as many bytes as its payload takes (its
// agenda holds hundreds of thousands): defined by the library, not part of the API.
struct MessageBytes;
}  // namespace detail

class Message {
 public:
  static constexpr size_t kCapacity = 56;

  template <typename T>
  static Message of(const T& payload) {
    static_assert(std::is_trivially_copyable_v<T>, "messages are plain data");
    static_assert(sizeof(T) <= kCapacity, "message payload too large");
    Message message;
    message.type_ = &kType<T>;
    std::memcpy(message.bytes_.data(), &payload, sizeof(T));
    return message;
  }

  // The payload if the message is a T, else null.
  template <typename T>
  const T* as() const {
    if (type_ != &kType<T>) return nullptr;
    return reinterpret_cast<const T*>(bytes_.data());
  }

  std::string_view typeName() const { return type_ ? type_->name : std::string_view(); }

 private:
  friend struct detail::MessageBytes;

  // One record per message type: its address identifies the type without RTTI, and it holds the
  // name and the payload's size, so that a message carries one pointer besides its payload.
  struct Type {
    std::string_view name;
    size_t size;
  };
  template <typename T>
  static inline const Type kType{T::kName, sizeof(T)};

  const Type* type_ = nullptr;
  alignas(8) std::array<unsigned char, kCapacity> bytes_{};
};

}  // namespace datomsim
