// diffuv: heap choices for the multi-source Dijkstra.
//
// The paper uses a min-heap with decrease-key; the Fibonacci heap is the
// textbook one for Dijkstra and is the default. The others are Boost.Heap's
// remaining mutable heaps, offered so that they can be benchmarked.
#ifndef DIFFUV_GRAPH_HEAP_TAGS_H
#define DIFFUV_GRAPH_HEAP_TAGS_H

#include <boost/heap/binomial_heap.hpp>
#include <boost/heap/d_ary_heap.hpp>
#include <boost/heap/fibonacci_heap.hpp>
#include <boost/heap/pairing_heap.hpp>

namespace diffuv {

/// `boost::heap::fibonacci_heap`: O(1) amortised decrease-key. The default.
struct Fibonacci_heap_tag {};
/// `boost::heap::pairing_heap`.
struct Pairing_heap_tag {};
/// `boost::heap::binomial_heap`.
struct Binomial_heap_tag {};
/// `boost::heap::d_ary_heap` with arity 4 and mutable handles.
struct Quaternary_heap_tag {};

namespace internal {

template <class Tag, class Node, class Compare>
struct Heap_selector;

template <class Node, class Compare>
struct Heap_selector<Fibonacci_heap_tag, Node, Compare> {
  using type = boost::heap::fibonacci_heap<Node, boost::heap::compare<Compare>>;
};
template <class Node, class Compare>
struct Heap_selector<Pairing_heap_tag, Node, Compare> {
  using type = boost::heap::pairing_heap<Node, boost::heap::compare<Compare>>;
};
template <class Node, class Compare>
struct Heap_selector<Binomial_heap_tag, Node, Compare> {
  using type = boost::heap::binomial_heap<Node, boost::heap::compare<Compare>>;
};
template <class Node, class Compare>
struct Heap_selector<Quaternary_heap_tag, Node, Compare> {
  using type = boost::heap::d_ary_heap<Node, boost::heap::arity<4>, boost::heap::mutable_<true>,
                                       boost::heap::compare<Compare>>;
};

/// A heap entry of the distance algorithms: a tentative distance and its vertex.
template <class Vertex>
struct Distance_node {
  double distance;
  Vertex vertex;
};

/// Boost.Heap heaps are max-heaps: "farther is lower" puts the smallest distance on top.
struct Farther {
  template <class Node>
  bool operator()(const Node& a, const Node& b) const { return a.distance > b.distance; }
};

/// The min-heap of tentative distances of the heap chosen by `HeapTag`.
template <class HeapTag, class Vertex>
using Min_distance_heap = typename Heap_selector<HeapTag, Distance_node<Vertex>, Farther>::type;

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_GRAPH_HEAP_TAGS_H
