//! Scene parser: any bytes must give a scene or an error, never a panic; a
//! parsed scene must run to a result or an error.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(scene) = persson_studies::scene::Scene::parse(std::path::Path::new("fuzz.json"), text) {
            let _ = scene.run();
        }
    }
});
