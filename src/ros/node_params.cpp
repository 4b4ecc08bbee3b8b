#include "node_params.h"

#include <ros/package.h>

#include <algorithm>
#include <iostream>
#include <sstream>

namespace roomba_rrt::nodes {
namespace {

using XmlRpc::XmlRpcValue;

/// A parameter's value as the user wrote it, for messages: 'fast', 3, true, a list, a map.
std::string show(XmlRpcValue& v) {
  std::ostringstream out;
  switch (v.getType()) {
    case XmlRpcValue::TypeString:
      out << "'" << static_cast<std::string>(v) << "' (a string)";
      break;
    case XmlRpcValue::TypeInt:
      out << static_cast<int>(v) << " (an integer)";
      break;
    case XmlRpcValue::TypeDouble:
      out << static_cast<double>(v) << " (a number)";
      break;
    case XmlRpcValue::TypeBoolean:
      out << (static_cast<bool>(v) ? "true" : "false");
      break;
    case XmlRpcValue::TypeArray:
      out << "a list";
      break;
    case XmlRpcValue::TypeStruct:
      out << "a map";
      break;
    default:
      out << "a value of another type";
      break;
  }
  return out.str();
}

bool isNumber(XmlRpcValue& v) {
  return v.getType() == XmlRpcValue::TypeDouble || v.getType() == XmlRpcValue::TypeInt;
}
double toDouble(XmlRpcValue& v) {
  return v.getType() == XmlRpcValue::TypeInt ? static_cast<int>(v) : static_cast<double>(v);
}

// How each supported type is read from a parameter's value; false when the value is not one.
bool convert(XmlRpcValue& v, double& out) {
  if (!isNumber(v)) return false;
  out = toDouble(v);
  return true;
}
bool convert(XmlRpcValue& v, int& out) {
  if (v.getType() != XmlRpcValue::TypeInt) return false;
  out = static_cast<int>(v);
  return true;
}
bool convert(XmlRpcValue& v, bool& out) {
  if (v.getType() != XmlRpcValue::TypeBoolean) return false;
  out = static_cast<bool>(v);
  return true;
}
bool convert(XmlRpcValue& v, std::string& out) {
  if (v.getType() != XmlRpcValue::TypeString) return false;
  out = static_cast<std::string>(v);
  return true;
}
bool convert(XmlRpcValue& v, std::vector<double>& out) {
  if (v.getType() != XmlRpcValue::TypeArray) return false;
  out.clear();
  for (int i = 0; i < v.size(); ++i) {
    if (!isNumber(v[i])) return false;
    out.push_back(toDouble(v[i]));
  }
  return true;
}

template <class T>
const char* typeName();
template <>
const char* typeName<double>() {
  return "a number";
}
template <>
const char* typeName<int>() {
  return "an integer";
}
template <>
const char* typeName<bool>() {
  return "true or false";
}
template <>
const char* typeName<std::string>() {
  return "a string";
}
template <>
const char* typeName<std::vector<double>>() {
  return "a list of numbers";
}

/// Edits between two names (Levenshtein), for "did you mean".
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

NodeParams::NodeParams(const ros::NodeHandle& private_nh) : nh_(private_nh) {}

NodeParams::~NodeParams() {
  for (const std::string& name : written_) nh_.deleteParam(name);
  // Deleting ~initial_pose/x, /y and /theta leaves ~initial_pose as an empty mapping, which
  // hasParam still sees (the next start with named robots took it for a pose given by the user):
  // remove the groups that the deletions emptied, the deepest first.
  std::set<std::string> groups;
  for (const std::string& name : written_) {
    for (std::size_t slash = name.rfind('/'); slash != std::string::npos && slash > 0;
         slash = name.rfind('/', slash - 1)) {
      groups.insert(name.substr(0, slash));
    }
  }
  for (auto group = groups.rbegin(); group != groups.rend(); ++group) {
    XmlRpcValue value;
    if (nh_.getParam(*group, value) && value.getType() == XmlRpcValue::TypeStruct &&
        value.size() == 0) {
      nh_.deleteParam(*group);
    }
  }
}

template <class T>
T NodeParams::get(const std::string& name, const T& fallback, bool write_back) {
  known_.insert(name);
  T value = fallback;
  XmlRpcValue raw;
  const bool was_set = nh_.getParam(name, raw);
  if (was_set && !convert(raw, value)) {
    throw std::invalid_argument("~" + name + ": must be " + typeName<T>() + ", got " + show(raw));
  }
  if (write_back) writeBack(name, value, was_set);
  return value;
}

template <class T>
void NodeParams::writeBack(const std::string& name, const T& value, bool was_set) {
  nh_.setParam(name, value);
  if (!was_set) written_.push_back(name);
}

template bool NodeParams::get(const std::string&, const bool&, bool);
template int NodeParams::get(const std::string&, const int&, bool);
template double NodeParams::get(const std::string&, const double&, bool);
template std::string NodeParams::get(const std::string&, const std::string&, bool);
template std::vector<double> NodeParams::get(const std::string&, const std::vector<double>&, bool);

std::vector<std::string> NodeParams::unknown() const {
  std::vector<std::string> all, unread;
  ros::param::getParamNames(all);
  const std::string prefix = nh_.getNamespace() + "/";
  for (const std::string& full : all) {
    if (full.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string name = full.substr(prefix.size());
    const bool read = std::any_of(known_.begin(), known_.end(), [&](const std::string& k) {
      return name == k || (!k.empty() && k.back() == '/' && name.compare(0, k.size(), k) == 0);
    });
    if (!read) unread.push_back(name);
  }
  return unread;
}

void NodeParams::warnUnknown() const {
  for (const std::string& name : unknown()) {
    std::string nearest;
    std::size_t best = 4;  // at most 3 edits count as a typo
    for (const std::string& k : known_) {
      const std::size_t d = distance(name, k);
      if (d < best) best = d, nearest = k;
    }
    ROS_WARN("%s: ~%s is not a parameter of this node%s; it is ignored",
             ros::this_node::getName().c_str(), name.c_str(),
             nearest.empty() ? "" : (" (did you mean ~" + nearest + "?)").c_str());
  }
}

std::string packageConfigFile(const std::string& file_name) {
  const std::string package = ros::package::getPath("roomba_rrt");
  if (package.empty()) return std::string(ROOMBA_RRT_CONFIG_DIR) + "/" + file_name;
  return package + "/config/" + file_name;
}

bool printedHelp(int argc, char** argv, const std::string& node, const std::string& what) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << "Usage: rosrun roomba_rrt " << node << " [_param:=value ...]\n"
                << what << "\nParameters, topics and services: doc/nodes.md (" << node << ").\n";
      return true;
    }
  }
  return false;
}

}  // namespace roomba_rrt::nodes
