#include "yaml_events.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <sstream>

namespace sdfc::yaml_events {

namespace {

// Mirrors yaml-cpp's NodeBuilder (the handler behind YAML::Load): the same
// events give the same tree, with the same marks and tags.
class Builder : public YAML::EventHandler {
 public:
  explicit Builder(Document& d) : doc_(d) { anchors_.push_back(0); }  // anchors count from 1

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    add(push(mark, anchor, Value::Kind::Null, {}));
  }
  void OnAlias(const YAML::Mark&, YAML::anchor_t anchor) override { add(anchors_.at(anchor)); }
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    const std::uint32_t id = push(mark, anchor, Value::Kind::Scalar, tag);
    doc_.values[id].scalar = value;
    add(id);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(push(mark, anchor, Value::Kind::Sequence, tag));
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(push(mark, anchor, Value::Kind::Map, tag));
  }
  void OnMapEnd() override { close(); }

 private:
  std::uint32_t push(const YAML::Mark& mark, YAML::anchor_t anchor, Value::Kind kind, const std::string& tag) {
    const auto id = static_cast<std::uint32_t>(doc_.values.size());
    Value& v = doc_.values.emplace_back();
    v.kind = kind;
    v.mark = mark;
    v.tag = tag_id(tag);
    if (anchor) anchors_.push_back(id);  // registered before its children, as NodeBuilder does
    return id;
  }
  std::uint32_t tag_id(const std::string& tag) {
    auto& tags = doc_.tags;
    for (std::uint32_t i = 0; i < 3; ++i)  // the shared ones; any other is stored as it comes
      if (tags[i] == tag) return i;
    tags.push_back(tag);
    return static_cast<std::uint32_t>(tags.size() - 1);
  }
  // A finished value: the root, or the next child of the open collection.
  void add(std::uint32_t id) {
    if (open_.empty()) {
      if (doc_.root < 0) doc_.root = id;
      return;
    }
    pending_.push_back(id);
  }
  void open(std::uint32_t id) { open_.push_back({id, pending_.size()}); }
  // Children collect on one shared stack and move to `kids` in one piece.
  void close() {
    const Open o = open_.back();
    open_.pop_back();
    Value& v = doc_.values[o.id];
    v.first = static_cast<std::uint32_t>(doc_.kids.size());
    v.count = static_cast<std::uint32_t>(pending_.size() - o.start);
    doc_.kids.insert(doc_.kids.end(), pending_.begin() + std::ptrdiff_t(o.start), pending_.end());
    pending_.resize(o.start);
    add(o.id);
  }

  struct Open {
    std::uint32_t id;
    size_t start;
  };
  Document& doc_;
  std::vector<std::uint32_t> anchors_;
  std::vector<Open> open_;
  std::vector<std::uint32_t> pending_;
};

}  // namespace

Document parse(const std::string& text) {
  Document doc;
  // A value takes at least 2 bytes of text ("1,"), most scenes 5 to 10:
  // reserved room that is never touched costs no memory, a regrowth copies all.
  doc.values.reserve(text.size() / 4);
  std::stringstream in(text);  // as YAML::Load(std::string) reads it
  YAML::Parser parser(in);
  Builder b(doc);
  if (!parser.HandleNextDocument(b)) doc.root = -1;
  return doc;
}

}  // namespace sdfc::yaml_events
