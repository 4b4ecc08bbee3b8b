// The blackboard: typed values that the nodes of one tree (and the application around it) share
// by key, as in BehaviorTree.CPP (`goal="{goal}" path="{path}"`).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <typeindex>

namespace roomba_rrt::bt {

/// The name of a port's value type in messages ("double", "Pose2D"). Specialize it for the
/// application's types (next to the type) so errors name them; the default is the mangled name.
template <class T>
struct TypeName {
  static std::string get() { return typeid(T).name(); }
};
template <>
struct TypeName<bool> {
  static std::string get() { return "bool"; }
};
template <>
struct TypeName<int> {
  static std::string get() { return "int"; }
};
template <>
struct TypeName<long> {
  static std::string get() { return "long"; }
};
template <>
struct TypeName<double> {
  static std::string get() { return "double"; }
};
template <>
struct TypeName<std::string> {
  static std::string get() { return "string"; }
};

/// Typed values by key. Keys are declared with their type before a tree is built (by the
/// application, or by the factory for the keys the tree file names); a key keeps its type
/// forever, and declaring it again with another type throws std::invalid_argument naming both.
///
/// Entries never move once declared: nodes keep a pointer to theirs (InputPort, OutputPort), so
/// a tick reads and writes a value without a lookup, a lock or an allocation. One tree is ticked
/// from one thread; the blackboard is not synchronized.
class Blackboard {
 public:
  /// What an entry is, whatever its type.
  struct EntryBase {
    EntryBase(std::type_index t, std::string name) : type(t), type_name(std::move(name)) {}
    virtual ~EntryBase() = default;
    std::type_index type;
    std::string type_name;
    /// How many times the value was written (0: never, so reading it gives nothing).
    std::uint64_t writes = 0;
  };

  /// An entry of type T.
  template <class T>
  struct Entry final : EntryBase {
    Entry() : EntryBase(typeid(T), TypeName<T>::get()) {}
    T value{};
    const T* get() const { return writes > 0 ? &value : nullptr; }
    void set(const T& v) {
      value = v;
      ++writes;
    }
    /// Forgets the value (reads give nothing until the next write; `writes` goes back to 0).
    void clear() { writes = 0; }
  };

  /// The entry of `key`, declared with type T if it is new (without a value).
  template <class T>
  Entry<T>& declare(const std::string& key) {
    auto it = entries_.find(key);
    if (it == entries_.end()) {
      it = entries_.emplace(key, std::make_unique<Entry<T>>()).first;
    } else if (it->second->type != typeid(T)) {
      throw std::invalid_argument("blackboard key '" + key + "' holds " + it->second->type_name +
                                  ", not " + TypeName<T>::get());
    }
    return static_cast<Entry<T>&>(*it->second);
  }

  /// Declares `key` (as declare()) and writes `value`.
  template <class T>
  Entry<T>& set(const std::string& key, const T& value) {
    Entry<T>& entry = declare<T>(key);
    entry.set(value);
    return entry;
  }

  /// The value of `key`, or nullptr when the key is unknown or was never written;
  /// std::invalid_argument when it holds another type.
  template <class T>
  const T* get(const std::string& key) const {
    const auto it = entries_.find(key);
    if (it == entries_.end()) return nullptr;
    if (it->second->type != typeid(T)) {
      throw std::invalid_argument("blackboard key '" + key + "' holds " + it->second->type_name +
                                  ", not " + TypeName<T>::get());
    }
    return static_cast<const Entry<T>&>(*it->second).get();
  }

  /// Calls f(key, entry) for every entry, by key (monitors: Groot2's blackboard dump).
  template <class F>
  void forEach(F&& f) const {
    for (const auto& [key, entry] : entries_) f(key, *entry);
  }

  /// The entry of `key`, or nullptr.
  const EntryBase* find(const std::string& key) const {
    const auto it = entries_.find(key);
    return it == entries_.end() ? nullptr : it->second.get();
  }
  EntryBase* find(const std::string& key) {
    const auto it = entries_.find(key);
    return it == entries_.end() ? nullptr : it->second.get();
  }

  /// The tree's clock: the number of the current tick (1 in the first tick; Tree::tick()
  /// advances it before ticking the root). Nodes that measure time (RateController) count ticks
  /// with it, so a tree needs no clock and stays deterministic.
  std::uint64_t tick() const { return tick_; }
  void advanceTick() { ++tick_; }

 private:
  std::uint64_t tick_ = 0;
  std::map<std::string, std::unique_ptr<EntryBase>> entries_;
};

}  // namespace roomba_rrt::bt
