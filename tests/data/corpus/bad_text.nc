netcdf? no, just text
