#include "parallel/corner_exchange.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace sf {

namespace {

// One tag for all corner messages: between two ranks they are matched in posting order (MPI
// does not let messages of one sender and tag overtake each other), one per direction per call.
constexpr int kCornerTag = 1717;

void check_mpi(int code, const char* call) {
  if (code == MPI_SUCCESS) {
    return;
  }
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw std::runtime_error(std::string("corner exchange: ") + call +
                           " failed: " + std::string(text, static_cast<std::size_t>(length)));
}

void check_size(std::size_t got, std::size_t want, const char* what) {
  if (got != want) {
    throw std::invalid_argument(std::string("corner exchange: ") + what + " holds " +
                                std::to_string(got) + " doubles, expected " + std::to_string(want));
  }
}

void check_fits_int(std::int64_t doubles) {
  if (doubles > INT_MAX) {
    throw std::invalid_argument("CornerExchange: " + std::to_string(doubles) +
                                " doubles in one buffer overflow an MPI count");
  }
}

}  // namespace

CornerExchange::CornerExchange(const RankPlan& plan, int width)
    : width_(width),
      rank_(plan.rank),
      ranks_(plan.ranks),
      n_corners_(plan.n_corners),
      receive_size_(plan.receive_size) {
  if (width < 1) {
    throw std::invalid_argument("CornerExchange: width " + std::to_string(width) +
                                " (at least 1 value per corner)");
  }
  send_offsets_.push_back(0);
  for (const RankNeighbour& k : plan.neighbours) {
    neighbour_ranks_.push_back(k.rank);
    send_slots_.insert(send_slots_.end(), k.send_slots.begin(), k.send_slots.end());
    send_offsets_.push_back(static_cast<int>(send_slots_.size()));
    receive_offsets_.push_back(k.receive_offset);
    receive_counts_.push_back(k.receive_count);
  }
  check_fits_int(std::int64_t{width} * static_cast<std::int64_t>(send_slots_.size()));
  check_fits_int(std::int64_t{width} * receive_size_);
  check_fits_int(std::int64_t{width} * n_corners_);
  send_buffer_.resize(static_cast<std::size_t>(width) * send_slots_.size());
  requests_.resize(2 * plan.neighbours.size(), MPI_REQUEST_NULL);
}

void CornerExchange::exchange(std::span<const double> corners, std::span<double> received,
                              MPI_Comm comm) {
  const auto w = static_cast<std::size_t>(width_);
  check_size(corners.size(), w * static_cast<std::size_t>(n_corners_), "the corner buffer");
  check_size(received.size(), w * static_cast<std::size_t>(receive_size_), "the receive buffer");
  int rank = -1;
  int ranks = 0;
  check_mpi(MPI_Comm_rank(comm, &rank), "MPI_Comm_rank");
  check_mpi(MPI_Comm_size(comm, &ranks), "MPI_Comm_size");
  if (rank != rank_ || ranks != ranks_) {
    throw std::invalid_argument("corner exchange: the plan is rank " + std::to_string(rank_) +
                                " of " + std::to_string(ranks_) + ", the communicator rank " +
                                std::to_string(rank) + " of " + std::to_string(ranks));
  }
  const std::size_t n = neighbour_ranks_.size();
  // Receives first, so that every message finds its buffer posted.
  for (std::size_t k = 0; k < n; ++k) {
    check_mpi(MPI_Irecv(received.data() + w * static_cast<std::size_t>(receive_offsets_[k]),
                        width_ * receive_counts_[k], MPI_DOUBLE, neighbour_ranks_[k], kCornerTag,
                        comm, &requests_[k]),
              "MPI_Irecv");
  }
  for (std::size_t i = 0; i < send_slots_.size(); ++i) {
    const double* from = corners.data() + w * static_cast<std::size_t>(send_slots_[i]);
    std::copy(from, from + w, send_buffer_.data() + w * i);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto begin = static_cast<std::size_t>(send_offsets_[k]);
    const int count = send_offsets_[k + 1] - send_offsets_[k];
    check_mpi(MPI_Isend(send_buffer_.data() + w * begin, width_ * count, MPI_DOUBLE,
                        neighbour_ranks_[k], kCornerTag, comm, &requests_[n + k]),
              "MPI_Isend");
  }
  check_mpi(MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE),
            "MPI_Waitall");
}

void gather_node_values(const RankPlan& plan, std::span<const double> corners,
                        std::span<const double> received, int width,
                        std::span<double> node_values) {
  if (width < 1) {
    throw std::invalid_argument("gather_node_values: width " + std::to_string(width));
  }
  const auto w = static_cast<std::size_t>(width);
  check_size(corners.size(), w * static_cast<std::size_t>(plan.n_corners), "the corner buffer");
  check_size(received.size(), w * static_cast<std::size_t>(plan.receive_size),
             "the receive buffer");
  check_size(node_values.size(), w * static_cast<std::size_t>(plan.n_nodes), "node_values");
  for (std::size_t i = 0; i < plan.nodes.size(); ++i) {
    double* sum = node_values.data() + w * static_cast<std::size_t>(plan.nodes[i]);
    std::fill(sum, sum + w, 0.0);
    for (int k = plan.gather_offsets[i]; k < plan.gather_offsets[i + 1]; ++k) {
      const int entry = plan.gather_entries[static_cast<std::size_t>(k)];
      const double* value = entry >= 0 ? corners.data() + w * static_cast<std::size_t>(entry)
                                       : received.data() + w * static_cast<std::size_t>(-1 - entry);
      for (std::size_t c = 0; c < w; ++c) {
        sum[c] += value[c];
      }
    }
  }
}

}  // namespace sf
