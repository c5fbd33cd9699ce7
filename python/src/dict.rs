//! A Python dict turned into TOML text, so that a scenario given as a dict goes through the
//! very loader and checks of a file (`Source::from_str`); its errors then name the dict path.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// The TOML text of `d`, a dict of str keys whose values are bool, int, float, str, lists
/// or tuples of these, or dicts again (numpy scalars and arrays count through `tolist`).
pub fn to_toml(d: &Bound<'_, PyDict>) -> PyResult<String> {
    let table = table(d, "")?;
    toml::to_string(&table)
        .map_err(|e| PyTypeError::new_err(format!("dict: cannot write it as TOML: {e}")))
}

fn table(d: &Bound<'_, PyDict>, path: &str) -> PyResult<toml::Table> {
    let mut t = toml::Table::new();
    for (k, v) in d.iter() {
        let Ok(key) = k.extract::<String>() else {
            return Err(PyTypeError::new_err(format!(
                "dict: key `{path}`: the keys of a scenario are strings, got {}",
                k.repr()?
            )));
        };
        let sub = if path.is_empty() {
            key.clone()
        } else {
            format!("{path}.{key}")
        };
        t.insert(key, value(&v, &sub)?);
    }
    Ok(t)
}

fn value(v: &Bound<'_, PyAny>, path: &str) -> PyResult<toml::Value> {
    // bool before int: a Python bool is an int.
    if v.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(v.extract()?));
    }
    if v.is_instance_of::<PyInt>() {
        return Ok(toml::Value::Integer(v.extract().map_err(|_| {
            PyTypeError::new_err(format!("dict: key `{path}`: integer out of range"))
        })?));
    }
    if v.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(v.extract()?));
    }
    if v.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(v.extract()?));
    }
    if let Ok(d) = v.cast::<PyDict>() {
        return Ok(toml::Value::Table(table(d, path)?));
    }
    if v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
        let mut items = Vec::new();
        for (i, item) in v.try_iter()?.enumerate() {
            items.push(value(&item?, &format!("{path}[{i}]"))?);
        }
        return Ok(toml::Value::Array(items));
    }
    // numpy arrays and scalars (np.int64, np.bool_), and anything else that lists itself.
    if v.hasattr("tolist")? {
        let listed = v.call_method0("tolist")?;
        if !listed.is(v) {
            return value(&listed, path);
        }
    }
    Err(PyTypeError::new_err(format!(
        "dict: key `{path}`: a scenario value is a bool, int, float, str, list or dict, got {}",
        v.get_type().name()?
    )))
}
