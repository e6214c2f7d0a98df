#include "geoshaping/edit_history.h"

#include "geoshaping/bit_cast.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace geoshaping
{
namespace
{
const char* const kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
constexpr std::size_t kVertexBytes = 4 + 3 * 8;

void put_bytes(std::vector<unsigned char>& out, std::uint64_t bits, int bytes)
{
  for (int i = 0; i < bytes; ++i)
    out.push_back(static_cast<unsigned char>(bits >> (8 * i)));
}

std::uint64_t get_bytes(const unsigned char* in, int bytes)
{
  std::uint64_t bits = 0;
  for (int i = 0; i < bytes; ++i)
    bits |= std::uint64_t(in[i]) << (8 * i);
  return bits;
}

std::string base64(const std::vector<unsigned char>& in)
{
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < in.size(); i += 3)
  {
    const std::size_t left = in.size() - i;
    const std::uint32_t b = (std::uint32_t(in[i]) << 16) |
                            (left > 1 ? std::uint32_t(in[i + 1]) << 8 : 0) |
                            (left > 2 ? in[i + 2] : 0);
    out += kBase64[(b >> 18) & 63];
    out += kBase64[(b >> 12) & 63];
    out += left > 1 ? kBase64[(b >> 6) & 63] : '=';
    out += left > 2 ? kBase64[b & 63] : '=';
  }
  return out;
}

bool unbase64(const std::string& in, std::vector<unsigned char>& out)
{
  if (in.size() % 4 != 0)
    return false;
  out.clear();
  for (std::size_t i = 0; i < in.size(); i += 4)
  {
    std::uint32_t b = 0;
    int pad = 0;
    for (int k = 0; k < 4; ++k)
    {
      const char c = in[i + k];
      const char* p = c ? std::strchr(kBase64, c) : nullptr;
      if (c == '=' && k >= 2)
        ++pad;
      else if (!p || pad)
        return false;
      b = (b << 6) | std::uint32_t(p ? p - kBase64 : 0);
    }
    out.push_back(static_cast<unsigned char>(b >> 16));
    if (pad < 2)
      out.push_back(static_cast<unsigned char>(b >> 8));
    if (pad < 1)
      out.push_back(static_cast<unsigned char>(b));
  }
  return true;
}

std::string hex(double x)
{
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%a", x);
  return buffer;
}

bool parse_number(std::istringstream& in, double& x)
{
  std::string token;
  if (!(in >> token))
    return false;
  errno = 0;
  char* end = nullptr;
  x = std::strtod(token.c_str(), &end);
  return end && *end == '\0' && errno == 0;
}

bool parse_integer(std::istringstream& in, long long& i)
{
  double x;
  if (!parse_number(in, x) || x != double(static_cast<long long>(x)))
    return false;
  i = static_cast<long long>(x);
  return true;
}
} // namespace

std::string encode_edit(const Edit& e)
{
  const EditRecipe& r = e.recipe;
  std::ostringstream out;
  out << "GSE1 " << r.grasp;
  for (double x : { r.displacement.x(), r.displacement.y(), r.displacement.z() })
    out << ' ' << hex(x);
  out << ' ' << r.queue;
  for (double x :
    { r.stretch[0], r.stretch[1], r.compression[0], r.compression[1], r.shear[0], r.shear[1] })
    out << ' ' << hex(x);
  out << ' ' << r.curve_shape << ' ' << hex(r.step_threshold) << ' ' << r.refinement_iterations
      << ' ' << e.vertices.size() << ' ';
  std::vector<unsigned char> payload;
  payload.reserve(e.vertices.size() * kVertexBytes);
  for (std::size_t i = 0; i < e.vertices.size(); ++i)
  {
    put_bytes(payload, std::uint32_t(e.vertices[i]), 4);
    for (int k = 0; k < 3; ++k)
      put_bytes(payload, bit_cast<std::uint64_t>(e.displacements[i][k]), 8);
  }
  out << base64(payload);
  return out.str();
}

bool decode_edit(const std::string& record, index_t n, Edit& e, std::string& error)
{
  std::istringstream in(record);
  std::string magic, payload;
  double d[13];
  long long grasp, queue, shape, refinement, count;
  in >> magic;
  bool ok = magic == "GSE1" && parse_integer(in, grasp) && parse_number(in, d[0]) &&
            parse_number(in, d[1]) && parse_number(in, d[2]) && parse_integer(in, queue);
  for (int k = 3; ok && k < 9; ++k)
    ok = parse_number(in, d[k]);
  ok = ok && parse_integer(in, shape) && parse_number(in, d[9]) && parse_integer(in, refinement) &&
       parse_integer(in, count);
  std::vector<unsigned char> bytes;
  if (ok && count > 0)
    ok = bool(in >> payload) && unbase64(payload, bytes);
  if (!ok || count < 0 || bytes.size() != std::size_t(count) * kVertexBytes)
  {
    error = "malformed edit record (expected GSE1 ...)";
    return false;
  }
  e = Edit{};
  EditRecipe& r = e.recipe;
  r.grasp = index_t(grasp);
  r.displacement = Eigen::Vector3d(d[0], d[1], d[2]);
  r.queue = int(queue);
  std::memcpy(r.stretch, d + 3, sizeof r.stretch);
  std::memcpy(r.compression, d + 5, sizeof r.compression);
  std::memcpy(r.shear, d + 7, sizeof r.shear);
  r.curve_shape = int(shape);
  r.step_threshold = d[9];
  r.refinement_iterations = int(refinement);
  e.vertices.resize(std::size_t(count));
  e.displacements.resize(std::size_t(count));
  for (std::size_t i = 0; i < std::size_t(count); ++i)
  {
    const unsigned char* p = bytes.data() + i * kVertexBytes;
    const auto v = static_cast<std::int32_t>(static_cast<std::uint32_t>(get_bytes(p, 4)));
    if (v < 0 || v >= n)
    {
      error = "edit moves vertex " + std::to_string(v) + ", outside [0, " + std::to_string(n) + ")";
      return false;
    }
    e.vertices[i] = v;
    for (int k = 0; k < 3; ++k)
      e.displacements[i][k] = bit_cast<double>(get_bytes(p + 4 + 8 * k, 8));
    if (!e.displacements[i].allFinite())
    {
      error = "edit has a non-finite displacement";
      return false;
    }
  }
  e.hash = record_hash(record);
  return true;
}

std::uint64_t record_hash(const std::string& record)
{
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : record)
    h = (h ^ c) * 1099511628211ull;
  return h;
}

void EditHistory::apply(ChainMailDeformer& deformer, Edit& e)
{
  deformer.reset();
  e.old_rest.resize(e.vertices.size());
  e.old_offset.resize(e.vertices.size());
  for (std::size_t i = 0; i < e.vertices.size(); ++i)
  {
    const index_t v = e.vertices[i];
    e.old_rest[i] = deformer.rest_local(v);
    e.old_offset[i] = deformer.committed_offset(v);
    deformer.set_rest(v, e.old_rest[i] + e.displacements[i], e.old_offset[i] + e.displacements[i]);
    touched_.push_back(v);
  }
}

void EditHistory::revert(ChainMailDeformer& deformer, const Edit& e)
{
  deformer.reset();
  // Backwards, so a vertex listed twice ends at its first saved value.
  for (std::size_t i = e.vertices.size(); i-- > 0;)
  {
    deformer.set_rest(e.vertices[i], e.old_rest[i], e.old_offset[i]);
    touched_.push_back(e.vertices[i]);
  }
}

const Edit& EditHistory::commit(ChainMailDeformer& deformer, const EditRecipe& recipe,
  const std::vector<index_t>& vertices, const std::vector<Eigen::Vector3d>& displacements)
{
  edits_.resize(applied_);
  Edit e;
  e.recipe = recipe;
  e.vertices = vertices;
  e.displacements = displacements;
  e.hash = record_hash(encode_edit(e));
  edits_.push_back(std::move(e));
  apply(deformer, edits_.back());
  ++applied_;
  return edits_.back();
}

bool EditHistory::undo(ChainMailDeformer& deformer)
{
  if (applied_ == 0)
    return false;
  revert(deformer, edits_[--applied_]);
  return true;
}

bool EditHistory::redo(ChainMailDeformer& deformer)
{
  if (applied_ == edits_.size())
    return false;
  apply(deformer, edits_[applied_++]);
  return true;
}

bool EditHistory::synchronize(ChainMailDeformer& deformer, const std::vector<std::string>& records,
  std::string& error, const std::function<bool(index_t)>& fits)
{
  // After the edit at applied_ - 1 was applied: drops it (and the redo tail) if a vertex
  // it moved does not fit.
  const auto refused = [&](std::size_t i)
  {
    if (!fits)
      return false;
    for (index_t v : edits_[applied_ - 1].vertices)
      if (!fits(v))
      {
        undo(deformer);
        edits_.resize(applied_);
        error = "edit " + std::to_string(i) + " moves vertex " + std::to_string(v) +
                " beyond what the output's points hold";
        return true;
      }
    return false;
  };
  std::vector<std::uint64_t> hashes(records.size());
  for (std::size_t i = 0; i < records.size(); ++i)
    hashes[i] = record_hash(records[i]);
  std::size_t common = 0;
  while (common < applied_ && common < records.size() && edits_[common].hash == hashes[common])
    ++common;
  while (applied_ > common)
    undo(deformer);
  for (std::size_t i = common; i < records.size(); ++i)
  {
    if (i < edits_.size() && edits_[i].hash == hashes[i])
    {
      redo(deformer);
      if (refused(i))
        return false;
      continue;
    }
    Edit e;
    if (!decode_edit(records[i], deformer.size(), e, error))
    {
      error = "edit " + std::to_string(i) + ": " + error;
      return false;
    }
    edits_.resize(applied_);
    edits_.push_back(std::move(e));
    redo(deformer);
    if (refused(i))
      return false;
  }
  return true;
}

void EditHistory::clear()
{
  edits_.clear();
  applied_ = 0;
  touched_.clear();
}

std::vector<index_t> EditHistory::take_touched()
{
  std::vector<index_t> out;
  out.swap(touched_);
  return out;
}

std::size_t EditHistory::memory_bytes() const
{
  std::size_t bytes = edits_.capacity() * sizeof(Edit) + touched_.capacity() * sizeof(index_t);
  for (const Edit& e : edits_)
    bytes += e.vertices.capacity() * sizeof(index_t) +
             (e.displacements.capacity() + e.old_rest.capacity() + e.old_offset.capacity()) *
               sizeof(Eigen::Vector3d);
  return bytes;
}

} // namespace geoshaping
