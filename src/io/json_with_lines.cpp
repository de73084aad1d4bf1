#include "io/json_with_lines.hpp"

#include <algorithm>
#include <cstring>
#include <exception>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <unordered_set>
#include <utility>

namespace cardemo::json_lines {
namespace {

// nlohmann 3.11 keeps no positions on values, so the parser reads through this iterator, which
// remembers the line of the last character consumed. The lexer reads one character past a number,
// so a number's line is the line of that look-ahead character counted *before* it (a '\n' right
// after a number still belongs to the number's line).
struct LineCursor {
  int newlines = 0;   // '\n' consumed so far
  int last_line = 1;  // line of the last character consumed
};

class CountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* p, LineCursor* cursor) : p_(p), cursor_(cursor) {}
  reference operator*() const { return *p_; }
  CountingIterator& operator++() {
    cursor_->last_line = cursor_->newlines + 1;
    if (*p_ == '\n') ++cursor_->newlines;
    ++p_;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p_ == o.p_; }

 private:
  const char* p_;
  LineCursor* cursor_;
};

// Builds the tree from SAX events; every container is open on `stack_`. Children are appended to
// the innermost open container only, so pointers to the enclosing ones stay valid.
class TreeBuilder {
 public:
  explicit TreeBuilder(const LineCursor& cursor) : cursor_(cursor) {}

  bool null() { return add(Node{}) != nullptr; }
  bool boolean(bool b) {
    Node n;
    n.kind = Node::Kind::kBool;
    n.boolean = b;
    return add(std::move(n)) != nullptr;
  }
  bool number_integer(std::int64_t v) { return number(static_cast<double>(v)); }
  bool number_unsigned(std::uint64_t v) { return number(static_cast<double>(v)); }
  bool number_float(double v, const std::string& /*raw*/) { return number(v); }
  bool string(std::string& s) {
    Node n;
    n.kind = Node::Kind::kString;
    n.text = std::move(s);
    return add(std::move(n)) != nullptr;
  }
  bool binary(nlohmann::json::binary_t& /*unused*/) { return fail("binary values are not JSON"); }
  bool start_object(std::size_t /*unknown*/) { return open(Node::Kind::kObject); }
  bool start_array(std::size_t /*unknown*/) { return open(Node::Kind::kArray); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(std::string& k) {
    Frame& f = stack_.back();
    if (!f.keys.insert(k).second) {
      const std::string where = path(false);
      return fail("duplicate key \"" + printable(k) + "\" in " + (where.empty() ? "scene" : where));
    }
    f.pending_key = std::move(k);
    f.pending_line = cursor_.last_line;
    f.has_pending_key = true;
    return true;
  }

  bool parse_error(std::size_t /*byte*/, const std::string& last_token,
                   const nlohmann::json::exception& ex) {
    const std::string where = path(true);
    if (ex.id == 406) {  // out_of_range.406: a number beyond double range, e.g. 1e999
      return fail((where.empty() ? std::string("value") : where) +
                  ": must be finite (number overflow: " + printable(last_token, 40) + ")");
    }
    std::string what = ex.what();
    constexpr std::string_view kPrefix = "syntax error while parsing ";
    if (const auto at = what.find(kPrefix); at != std::string::npos) {
      what.erase(0, at + kPrefix.size());
      if (const auto dash = what.find(" - "); dash != std::string::npos) what.erase(0, dash + 3);
    }
    return fail("invalid JSON" + (where.empty() ? std::string() : " in " + where) + ": " +
                printable(what, 120));
  }

  bool fail(std::string message) {
    if (!error_) error_ = SyntaxError{cursor_.last_line, std::move(message)};
    return false;
  }

  std::optional<SyntaxError> error_;
  Node root_;

 private:
  struct Frame {
    Node* node = nullptr;
    std::unordered_set<std::string> keys;
    std::string pending_key;
    int pending_line = 0;
    bool has_pending_key = false;
  };

  bool number(double v) {
    Node n;
    n.kind = Node::Kind::kNumber;
    n.number = v;
    return add(std::move(n)) != nullptr;
  }

  bool open(Node::Kind kind) {
    if (stack_.size() >= static_cast<std::size_t>(kMaxDepth)) {
      return fail("nesting deeper than " + std::to_string(kMaxDepth) + " levels");
    }
    Node n;
    n.kind = kind;
    Node* p = add(std::move(n));
    if (p == nullptr) return false;
    stack_.push_back(Frame{p, {}, {}, 0, false});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return true;
  }

  Node* add(Node n) {
    if (++values_ > kMaxValues) {
      fail("more than " + std::to_string(kMaxValues) + " JSON values");
      return nullptr;
    }
    n.line = cursor_.last_line;
    if (stack_.empty()) {
      root_ = std::move(n);
      return &root_;
    }
    Frame& f = stack_.back();
    if (f.node->kind == Node::Kind::kArray) {
      f.node->items.push_back(std::move(n));
      return &f.node->items.back();
    }
    f.node->members.push_back(Member{std::move(f.pending_key), f.pending_line, std::move(n)});
    f.has_pending_key = false;
    return &f.node->members.back().value;
  }

  // Field path like `parked[2].width`; with `pending`, includes the element being read now.
  [[nodiscard]] std::string path(bool pending) const {
    std::string out;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const Frame& f = stack_[i];
      const bool innermost = i + 1 == stack_.size();
      if (innermost && !pending) break;
      if (f.node->kind == Node::Kind::kArray) {
        const std::size_t n = f.node->items.size();
        if (!innermost && n == 0) break;
        // Appended piecewise: `"[" + std::string` makes GCC 12 at -O3 warn falsely (bug 105651).
        out += '[';
        out += std::to_string(innermost ? n : n - 1);
        out += ']';
      } else {
        if (innermost && !f.has_pending_key) break;
        if (!innermost && f.node->members.empty()) break;
        if (!out.empty()) out += '.';
        out += printable(innermost ? f.pending_key : f.node->members.back().key);
      }
    }
    return out;
  }

  const LineCursor& cursor_;
  std::vector<Frame> stack_;
  std::size_t values_ = 0;
};

}  // namespace

const Node* Node::find(std::string_view key) const {
  for (const Member& m : members) {
    if (m.key == key) return &m.value;
  }
  return nullptr;
}

const char* kindName(Node::Kind kind) {
  switch (kind) {
    case Node::Kind::kNull:
      return "null";
    case Node::Kind::kBool:
      return "a boolean";
    case Node::Kind::kNumber:
      return "a number";
    case Node::Kind::kString:
      return "a string";
    case Node::Kind::kArray:
      return "an array";
    case Node::Kind::kObject:
      return "an object";
  }
  return "a value";
}

std::variant<Node, SyntaxError> parse(std::string_view text) {
  // The lexer takes a NUL byte for the end of input, which would silently drop what follows.
  if (const void* nul = std::memchr(text.data(), '\0', text.size()); nul != nullptr) {
    const auto offset = static_cast<const char*>(nul) - text.data();
    const auto before = text.substr(0, static_cast<std::size_t>(offset));
    const int line = 1 + static_cast<int>(std::count(before.begin(), before.end(), '\n'));
    return SyntaxError{line, "NUL byte in the file (binary data is not JSON)"};
  }
  LineCursor cursor;
  TreeBuilder builder(cursor);
  try {
    const CountingIterator first(text.data(), &cursor);
    const CountingIterator last(text.data() + text.size(), &cursor);
    const bool ok = nlohmann::json::sax_parse(first, last, &builder);
    if (!ok || builder.error_) {
      if (!builder.error_) builder.fail("invalid JSON");
      return *builder.error_;
    }
  } catch (const std::exception& e) {
    return SyntaxError{cursor.last_line, "cannot read JSON: " + printable(e.what(), 120)};
  }
  return std::move(builder.root_);
}

}  // namespace cardemo::json_lines
