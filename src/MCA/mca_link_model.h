/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

#ifndef LMP_MCA_LINK_MODEL_H
#define LMP_MCA_LINK_MODEL_H

#include "mca_link_layout.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   the link model of a pair style with persistent links, host side: the
   parts it is made of (the elastic part always, first; optional parts as
   the pair style's keywords select them), each with the block of history
   values it keeps per link and of law state per automaton.  The model
   lays the blocks out one after the other; the links fix takes its row
   widths from it (as fix neigh/history takes dnum from a pair style) and
   restart files record the blocks by name and size (FixMCALinks).
------------------------------------------------------------------------- */

class MCALinkModel {
 public:
  struct Block {
    std::string name;    // the part's name, as restart files record it
    int link_size;       // doubles per link row
    int atom_size;       // doubles of law state per automaton
  };

  MCALinkModel()
  {
    for (int p = 0; p < MCAKernels::MAX_PARTS; p++)
      layout_.link_offset[p] = layout_.atom_offset[p] = -1;
  }

  // exact_slots: the slots of the block (a bit each) that a row in
  // precision mixed keeps in double (MCALinkPartInfo)
  void add_part(int part, const std::string &name, int link_size, int atom_size,
                unsigned exact_slots = 0u)
  {
    if (part >= 0 && part < MCAKernels::MAX_PARTS) {
      layout_.link_offset[part] = layout_.row_size;
      layout_.atom_offset[part] = layout_.atom_size;
    }
    for (int k = 0; k < link_size && k < 32; k++) {
      const int slot = layout_.row_size + k;
      if ((exact_slots >> k & 1u) && slot < MCAKernels::MAX_ROW_SIZE) {
        layout_.exact[slot / 32] |= 1u << (slot % 32);
        layout_.exact_count++;
      }
    }
    layout_.row_size += link_size;
    layout_.atom_size += atom_size;
    blocks_.push_back(Block{name, link_size, atom_size});
    update_storage();
  }

  // rows stored in doubles (false) or in precision mixed (true)
  void set_mixed(bool mixed)
  {
    layout_.mixed = mixed ? 1 : 0;
    update_storage();
  }
  bool mixed() const { return layout_.mixed != 0; }
  const char *precision() const { return mixed() ? "mixed" : "double"; }

  const std::vector<Block> &blocks() const { return blocks_; }
  const MCAKernels::MCALinkLayout &layout() const { return layout_; }
  bool same_blocks(const MCALinkModel &other) const
  {
    if (blocks_.size() != other.blocks_.size()) return false;
    for (size_t k = 0; k < blocks_.size(); k++)
      if (blocks_[k].name != other.blocks_[k].name ||
          blocks_[k].link_size != other.blocks_[k].link_size ||
          blocks_[k].atom_size != other.blocks_[k].atom_size)
        return false;
    return true;
  }
  std::string names() const
  {
    std::string text;
    for (const auto &b : blocks_) text += (text.empty() ? "" : " ") + b.name;
    return text;
  }
  // "name link_size atom_size ..." (the blocks, as messages name them)
  std::string describe() const
  {
    std::string text;
    for (const auto &b : blocks_)
      text += (text.empty() ? "" : " ") + b.name + " " + std::to_string(b.link_size) + " " +
          std::to_string(b.atom_size);
    return text;
  }
  // the arguments of the links fix: the blocks, and the precision where
  // it is not double
  std::string fix_arguments() const { return describe() + (mixed() ? " precision mixed" : ""); }

 private:
  std::vector<Block> blocks_;
  MCAKernels::MCALinkLayout layout_ = {};

  // a mixed row: its exact slots in doubles, then the others in floats,
  // two to a double
  void update_storage()
  {
    const int floats = layout_.row_size - layout_.exact_count;
    layout_.stored_size = layout_.mixed ? layout_.exact_count + (floats + 1) / 2 : layout_.row_size;
  }
};

}    // namespace LAMMPS_NS

#endif
