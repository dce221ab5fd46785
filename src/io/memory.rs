//! Input files held in memory, for a host without a file system.
//!
//! In a browser the user's files never reach a disk: the page hands their
//! bytes to [`mount`] under the names a scene gives them, and every reader
//! of the crate ([`super::read`]) finds them there before it looks on disk.
//! The table is process-wide; [`unmount_all`] empties it.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};

type Table = BTreeMap<PathBuf, Arc<[u8]>>;

static FILES: Mutex<Table> = Mutex::new(BTreeMap::new());

fn with<T>(f: impl FnOnce(&mut Table) -> T) -> T {
    f(&mut FILES.lock().unwrap_or_else(PoisonError::into_inner))
}

/// Hold `bytes` as the input file `path` (replacing any held under it).
pub fn mount(path: impl Into<PathBuf>, bytes: Vec<u8>) {
    with(|t| t.insert(path.into(), bytes.into()));
}

/// Forget every file [`mount`] holds.
pub fn unmount_all() {
    with(BTreeMap::clear);
}

/// The file held as `path`, if any.
pub(crate) fn get(path: &Path) -> Option<Arc<[u8]>> {
    with(|t| t.get(path).cloned())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mounted_file_is_read_before_the_disk() {
        let p = Path::new("/no/such/dir/mounted-test.csv");
        assert!(super::super::read(p).is_err());
        mount(p, b"1 2\n".to_vec());
        assert_eq!(super::super::read(p).unwrap(), b"1 2\n");
        assert_eq!(super::super::read_head(p, 2).unwrap(), b"1 ");
        mount(p, b"3".to_vec());
        assert_eq!(super::super::read(p).unwrap(), b"3");
        assert_eq!(super::super::read_head(p, 8).unwrap(), b"3");
        with(|t| t.remove(p));
        assert!(super::super::read(p).is_err());
    }
}
