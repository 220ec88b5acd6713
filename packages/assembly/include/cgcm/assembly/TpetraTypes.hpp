#pragma once
// The one Tpetra type set of the Debian Trilinos build (double, int, long long, Serial).
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "cgcm/core/Types.hpp"

namespace cgcm::assembly {

using Node = Tpetra::Map<>::node_type;
using Map = Tpetra::Map<LocalIndex, GlobalIndex, Node>;
using Vector = Tpetra::Vector<Real, LocalIndex, GlobalIndex, Node>;
using MultiVector = Tpetra::MultiVector<Real, LocalIndex, GlobalIndex, Node>;
using Graph = Tpetra::FECrsGraph<LocalIndex, GlobalIndex, Node>;
using Matrix = Tpetra::FECrsMatrix<Real, LocalIndex, GlobalIndex, Node>;
using CrsMatrix = Tpetra::CrsMatrix<Real, LocalIndex, GlobalIndex, Node>;
using Operator = Tpetra::Operator<Real, LocalIndex, GlobalIndex, Node>;
using Import = Tpetra::Import<LocalIndex, GlobalIndex, Node>;
using Export = Tpetra::Export<LocalIndex, GlobalIndex, Node>;
using Comm = Teuchos::Comm<int>;
using ExecSpace = Node::execution_space;

static_assert(std::is_same_v<Map::global_ordinal_type, GlobalIndex>, "Tpetra global ordinal mismatch");

}  // namespace cgcm::assembly
