//! Every reader added after 0.4 on damaged copies of its example file: each
//! copy with a few bytes overwritten at random places (a seed-stable LCG),
//! or cut at a random length, reads to finite heights and sizes or to an
//! error naming the file, never a panic. (The fuzz target `read_formats`
//! does the same with coverage guidance, on nightly Rust.)

use persson::topography::read::{self, ReadOptions};

use super::support::{data, temp};

const FILES: &[&str] = &[
    "frt-2.frt",
    "opd-1-crop.opd",
    "opdx-3.opdx",
    "mi-1-crop.mi",
    "stp-1-crop.stp",
    "top-1.top",
    "nid-1-crop.nid",
    "nms-1-crop.nms",
    "mnt-1-crop.mnt",
    "example_ps-crop.tiff",
    "mitutoyo_mock.xlsx",
    "multiple_data_sets-crop.h5",
    "datx-float32.datx",
    "sdf-2-binary.sdf",
    "tmd-1.tmd",
    "bcrf-1-crop.bcrf",
    "matrix-4.txt.gz",
    "container-2.zip",
];
/// Damaged copies per file.
const COPIES: u64 = 60;

#[test]
fn damaged_copies_of_every_new_format_never_panic() {
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = move || {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        x >> 16
    };
    let mut errors = 0;
    for name in FILES {
        let bytes = std::fs::read(data(name)).unwrap();
        for k in 0..COPIES {
            let mut b = bytes.clone();
            if k % 3 == 0 {
                b.truncate(next() as usize % b.len());
            } else {
                // Bytes in the first 4 kB (headers) or anywhere.
                let span = if k % 3 == 1 {
                    b.len().min(4096)
                } else {
                    b.len()
                };
                for _ in 0..1 + next() % 4 {
                    let at = next() as usize % span;
                    b[at] = next() as u8;
                }
            }
            let path = temp(&format!("m{k}-{name}"), &b);
            let options = ReadOptions {
                fill_undefined: true,
                channel: name.ends_with(".zip").then(|| "1".to_string()),
                ..Default::default()
            };
            match read::read(&path, &options) {
                Ok(t) => {
                    assert!(t.heights().iter().all(|h| h.is_finite()), "{name} copy {k}");
                    assert!(t.lx() > 0.0 && t.lx().is_finite(), "{name} copy {k}");
                }
                Err(e) => {
                    let e = e.to_string();
                    let file = path.file_name().unwrap().to_string_lossy();
                    assert!(e.contains(&*file), "{name} copy {k}: {e}");
                    errors += 1;
                }
            }
            let _ = std::fs::remove_file(&path);
        }
    }
    assert!(errors > 0);
}
