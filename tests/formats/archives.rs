//! Zip archives that inflate beyond what a reader takes (`.xlsx` parts,
//! dataset members): an error naming the file and the part, read no
//! further (a small archive cannot make the reader allocate gigabytes).

use std::io::{Read, Write};

use persson::topography::read::ReadOptions;

use super::support::{data, error_of, temp};

/// `mitutoyo_mock.xlsx` with every worksheet replaced by 40 MiB of empty
/// cells (the reader takes parts up to 32 MiB): 40 kB compressed.
#[test]
fn an_xlsx_whose_sheet_inflates_beyond_the_limit_is_refused() {
    let bytes = std::fs::read(data("mitutoyo_mock.xlsx")).unwrap();
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(bytes)).unwrap();
    let mut zw = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for i in 0..zip.len() {
        let mut f = zip.by_index(i).unwrap();
        let name = f.name().unwrap().to_string();
        let mut content = Vec::new();
        f.read_to_end(&mut content).unwrap();
        if name.starts_with("xl/worksheets/") {
            content = b"<c r=\"A1\"/>".repeat((40 << 20) / 11);
        }
        zw.start_file(name, options).unwrap();
        zw.write_all(&content).unwrap();
    }
    let bomb = zw.finish().unwrap().into_inner();
    assert!(bomb.len() < 1 << 20, "{} bytes", bomb.len());
    let e = error_of(
        &temp("bomb.xlsx", &bomb),
        &ReadOptions::default(),
        "Mitutoyo SurfTest .xlsx: member \"xl/worksheets/",
    );
    assert!(e.contains("more than 33554432 is not read"), "{e}");
}
