#include "dream/barriers/linear_inequalities.h"

#include <stdexcept>

namespace dream::barriers {

void LinearInequalities::Reset(int num_variables) {
  num_variables_ = num_variables;
  row_start_.assign(1, 0);
  columns_.clear();
  values_.clear();
  bounds_.clear();
}

void LinearInequalities::AddRow(std::initializer_list<int> columns, std::initializer_list<double> values,
                                double bound) {
  if (columns.size() != values.size()) throw std::invalid_argument("LinearInequalities: columns and values differ");
  for (int column : columns) {
    if (column < 0 || column >= num_variables_) throw std::out_of_range("LinearInequalities: column out of range");
  }
  columns_.insert(columns_.end(), columns);
  values_.insert(values_.end(), values);
  row_start_.push_back(static_cast<int>(columns_.size()));
  bounds_.push_back(bound);
}

void LinearInequalities::Multiply(const Eigen::VectorXd& x, Eigen::VectorXd* out) const {
  out->resize(num_rows());
  for (int row = 0; row < num_rows(); ++row) {
    double sum = 0.0;
    for (int entry = row_begin(row); entry < row_end(row); ++entry) sum += value(entry) * x[column(entry)];
    (*out)[row] = sum;
  }
}

void LinearInequalities::MultiplyTransposed(const Eigen::VectorXd& y, Eigen::VectorXd* out) const {
  out->setZero(num_variables_);
  for (int row = 0; row < num_rows(); ++row) {
    for (int entry = row_begin(row); entry < row_end(row); ++entry) (*out)[column(entry)] += value(entry) * y[row];
  }
}

Eigen::MatrixXd LinearInequalities::Dense() const {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(num_rows(), num_variables_);
  for (int row = 0; row < num_rows(); ++row) {
    for (int entry = row_begin(row); entry < row_end(row); ++entry) dense(row, column(entry)) += value(entry);
  }
  return dense;
}

}  // namespace dream::barriers
