#include "geoshaping/edit/edit_history.h"

#include "geoshaping/mesh/bit_cast.h"
#include "geoshaping/parallel/partitioned_chainmail.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <sstream>

namespace geoshaping
{
namespace
{
const char* const kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
std::size_t entry_bytes(int version)
{
  return (version == 1 ? 4 : 8) + 3 * 8;
}

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
  out << (e.version == 1 ? "GSE1 " : "GSE2 ") << r.grasp;
  for (double x : { r.displacement.x(), r.displacement.y(), r.displacement.z() })
    out << ' ' << hex(x);
  out << ' ' << r.queue;
  for (double x :
    { r.stretch[0], r.stretch[1], r.compression[0], r.compression[1], r.shear[0], r.shear[1] })
    out << ' ' << hex(x);
  out << ' ' << r.curve_shape << ' ' << hex(r.step_threshold) << ' ' << r.refinement_iterations
      << ' ' << e.ids.size() << ' ';
  std::vector<unsigned char> payload;
  payload.reserve(e.ids.size() * entry_bytes(e.version));
  for (std::size_t i = 0; i < e.ids.size(); ++i)
  {
    if (e.version == 1)
      put_bytes(payload, std::uint32_t(e.ids[i]), 4);
    else
      put_bytes(payload, std::uint64_t(e.ids[i]), 8);
    for (int k = 0; k < 3; ++k)
      put_bytes(payload, bit_cast<std::uint64_t>(e.displacements[i][k]), 8);
  }
  out << base64(payload);
  return out.str();
}

bool decode_edit(const std::string& record, Edit& e, std::string& error)
{
  std::istringstream in(record);
  std::string magic, payload;
  double d[13];
  long long grasp, queue, shape, refinement, count;
  in >> magic;
  const int version = magic == "GSE1" ? 1 : magic == "GSE2" ? 2 : 0;
  bool ok = version > 0 && parse_integer(in, grasp) && parse_number(in, d[0]) &&
            parse_number(in, d[1]) && parse_number(in, d[2]) && parse_integer(in, queue);
  for (int k = 3; ok && k < 9; ++k)
    ok = parse_number(in, d[k]);
  ok = ok && parse_integer(in, shape) && parse_number(in, d[9]) && parse_integer(in, refinement) &&
       parse_integer(in, count);
  std::vector<unsigned char> bytes;
  if (ok && count > 0)
    ok = bool(in >> payload) && unbase64(payload, bytes);
  const std::size_t size = entry_bytes(version);
  if (!ok || count < 0 || bytes.size() != std::size_t(count) * size)
  {
    error = "malformed edit record (expected GSE2 ... or GSE1 ...)";
    return false;
  }
  e = Edit{};
  e.version = version;
  EditRecipe& r = e.recipe;
  r.grasp = std::int64_t(grasp);
  r.displacement = Eigen::Vector3d(d[0], d[1], d[2]);
  r.queue = int(queue);
  std::memcpy(r.stretch, d + 3, sizeof r.stretch);
  std::memcpy(r.compression, d + 5, sizeof r.compression);
  std::memcpy(r.shear, d + 7, sizeof r.shear);
  r.curve_shape = int(shape);
  r.step_threshold = d[9];
  r.refinement_iterations = int(refinement);
  e.ids.resize(std::size_t(count));
  e.displacements.resize(std::size_t(count));
  for (std::size_t i = 0; i < std::size_t(count); ++i)
  {
    const unsigned char* p = bytes.data() + i * size;
    const std::int64_t id =
      version == 1
        ? std::int64_t(static_cast<std::int32_t>(static_cast<std::uint32_t>(get_bytes(p, 4))))
        : static_cast<std::int64_t>(get_bytes(p, 8));
    if (version == 2 && i > 0 && id <= e.ids[i - 1])
    {
      error = "edit record's ids are not increasing (at id " + std::to_string(id) + ")";
      return false;
    }
    e.ids[i] = id;
    for (int k = 0; k < 3; ++k)
      e.displacements[i][k] = bit_cast<double>(get_bytes(p + size - 24 + 8 * k, 8));
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

void GlobalIdMap::set(const std::int64_t* gid, index_t n)
{
  local_.clear();
  if (!gid)
    return;
  local_.reserve(std::size_t(n));
  for (index_t v = 0; v < n; ++v)
    if (!local_.emplace(gid[v], v).second)
    {
      local_.clear(); // not distinct: not ids
      return;
    }
}

EditPlace GlobalIdMap::place() const
{
  EditPlace place;
  if (!local_.empty())
    place.holders = [this](std::int64_t id, std::vector<index_t>& out)
    {
      const index_t v = find(id);
      if (v >= 0)
        out.push_back(v);
    };
  return place;
}

void EditHistory::locate(const ChainMailDeformer& deformer, Edit& e, const EditPlace& place)
{
  e.vertices.clear();
  e.entries.clear();
  e.owned = 0;
  // Ids are vertex indices without holders, and in GSE1 records on a whole mesh.
  const bool by_index = !place.holders || (e.version == 1 && !place.exchange);
  std::vector<index_t> holders;
  for (std::size_t k = 0; k < e.ids.size(); ++k)
  {
    holders.clear();
    if (!by_index)
      place.holders(e.ids[k], holders);
    else if (e.ids[k] >= 0 && e.ids[k] < deformer.size())
      holders.push_back(index_t(e.ids[k]));
    bool owned = false;
    for (index_t v : holders)
    {
      e.vertices.push_back(v);
      e.entries.push_back(std::uint32_t(k));
      owned = owned || deformer.owned(v);
    }
    e.owned += owned;
  }
}

void EditHistory::apply(ChainMailDeformer& deformer, Edit& e)
{
  deformer.reset();
  e.old_rest.resize(e.vertices.size());
  e.old_offset.resize(e.vertices.size());
  for (std::size_t i = 0; i < e.vertices.size(); ++i)
  {
    const index_t v = e.vertices[i];
    const Eigen::Vector3d& u = e.displacements[e.entries[i]];
    e.old_rest[i] = deformer.rest_local(v);
    e.old_offset[i] = deformer.committed_offset(v);
    deformer.set_rest(v, e.old_rest[i] + u, e.old_offset[i] + u);
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
  const std::vector<index_t>& vertices, const std::vector<Eigen::Vector3d>& displacements,
  const EditPlace& place)
{
  edits_.resize(applied_);
  Edit e;
  e.recipe = recipe;
  // This piece's entries: its owned vertices, by global id (by index without holders).
  std::vector<std::int64_t> flat; // id, u as bits
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const index_t v = vertices[i];
    if (!deformer.owned(v))
      continue;
    flat.push_back(place.holders ? deformer.global_id(v) : std::int64_t(v));
    for (int k = 0; k < 3; ++k)
      flat.push_back(bit_cast<std::int64_t>(displacements[i][k]));
  }
  std::vector<std::vector<std::int64_t>> all;
  if (place.exchange)
    all = place.exchange->all_gather(flat);
  else
    all.push_back(std::move(flat));
  std::vector<std::pair<std::int64_t, Eigen::Vector3d>> entries;
  for (const auto& piece : all)
    for (std::size_t i = 0; i + 3 < piece.size(); i += 4)
      entries.emplace_back(
        piece[i], Eigen::Vector3d(bit_cast<double>(piece[i + 1]), bit_cast<double>(piece[i + 2]),
                    bit_cast<double>(piece[i + 3])));
  std::sort(
    entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [id, u] : entries)
  {
    e.ids.push_back(id);
    e.displacements.push_back(u);
  }
  locate(deformer, e, place);
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

bool EditHistory::refused(ChainMailDeformer& deformer, std::size_t i,
  const std::function<bool(index_t)>& fits, const EditPlace& place, std::string& error)
{
  const Edit& e = edits_[applied_ - 1];
  // Whether every id is owned somewhere, and the lowest id that does not fit.
  std::int64_t owned = std::int64_t(e.owned), unfit = 0, unfit_id = 0;
  if (fits)
    for (std::size_t k = 0; k < e.vertices.size(); ++k)
    {
      const std::int64_t id = e.ids[e.entries[k]];
      if (!fits(e.vertices[k]) && (!unfit || id < unfit_id))
        unfit = 1, unfit_id = id;
    }
  if (place.exchange)
  {
    owned = 0;
    std::int64_t any = 0;
    for (const auto& v : place.exchange->all_gather({ std::int64_t(e.owned), unfit, unfit_id }))
    {
      owned += v[0];
      if (v[1] && (!any || v[2] < unfit_id))
        unfit_id = v[2];
      any = any || v[1];
    }
    unfit = any;
  }
  if (owned == std::int64_t(e.ids.size()) && !unfit)
    return false;
  error = unfit ? "edit " + std::to_string(i) + " moves vertex " + std::to_string(unfit_id) +
                    " beyond what the output's points hold"
                : "edit " + std::to_string(i) + " moves " +
                    std::to_string(std::int64_t(e.ids.size()) - owned) + " of its " +
                    std::to_string(e.ids.size()) + " point ids that are not in the mesh";
  undo(deformer);
  edits_.resize(applied_);
  return true;
}

bool EditHistory::synchronize(ChainMailDeformer& deformer, const std::vector<std::string>& records,
  std::string& error, const std::function<bool(index_t)>& fits, const EditPlace& place)
{
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
      if (refused(deformer, i, fits, place, error))
        return false;
      continue;
    }
    Edit e;
    if (!decode_edit(records[i], e, error))
    {
      error = "edit " + std::to_string(i) + ": " + error;
      return false;
    }
    locate(deformer, e, place);
    edits_.resize(applied_);
    edits_.push_back(std::move(e));
    redo(deformer);
    if (refused(deformer, i, fits, place, error))
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
    bytes += e.ids.capacity() * sizeof(std::int64_t) + e.vertices.capacity() * sizeof(index_t) +
             e.entries.capacity() * sizeof(std::uint32_t) +
             (e.displacements.capacity() + e.old_rest.capacity() + e.old_offset.capacity()) *
               sizeof(Eigen::Vector3d);
  return bytes;
}

} // namespace geoshaping
