//! The readers of the instrument formats added after 0.4, each on
//! SurfaceTopography's example files (`tests/data/`, origins and licences in
//! `tests/data/README.md`) against SurfaceTopography 1.27.1 reading the same
//! file (`tests/reference/*_surface_topography.py`), then on damaged copies.
#![cfg(feature = "topography")]

#[path = "formats/archives.rs"]
mod archives;
#[path = "formats/channels.rs"]
mod channels;
#[path = "formats/dataset.rs"]
mod dataset;
#[path = "formats/frt_opd_opdx.rs"]
mod frt_opd_opdx;
#[path = "formats/gzip_sdf_tmd_bcr.rs"]
mod gzip_sdf_tmd_bcr;
#[path = "formats/hdf5_datx.rs"]
mod hdf5_datx;
#[path = "formats/mi_wsxm_nid_nms.rs"]
mod mi_wsxm_nid_nms;
#[path = "formats/mnt_tiff_xlsx.rs"]
mod mnt_tiff_xlsx;
#[path = "formats/mutations.rs"]
mod mutations;
#[path = "formats/support.rs"]
mod support;
