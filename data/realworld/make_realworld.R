# Writes the real-data corpus of this directory from R's own data sets
# (packages datasets and boot, shipped with R):  Rscript make_realworld.R
# Rows with NA are skipped (their x is kept, so the spacing becomes uneven).
w <- function(file, comment, xname, yname, x, y) {
  ok <- !is.na(x) & !is.na(y)
  con <- file(file, "w")
  writeLines(paste("#", comment), con)
  writeLines(paste(xname, yname, sep = ","), con)
  writeLines(paste(format(x[ok], scientific = FALSE, trim = TRUE, digits = 10),
                   format(y[ok], scientific = FALSE, trim = TRUE, digits = 10), sep = ","), con)
  close(con)
}
tx <- function(s) round(as.numeric(time(s)), 4)
w("nile.csv", c("Annual flow of the river Nile at Aswan, 1871-1970, 10^8 m^3.",
  "Source: R datasets::Nile (Durbin and Koopman 2001; Cobb 1978)."),
  "year", "flow", tx(Nile), as.numeric(Nile))
aq <- datasets::airquality
w("airquality_ozone.csv", c("Daily mean ozone (ppb, 13:00-15:00) at Roosevelt Island, New York,",
  "1 May - 30 Sep 1973; x = day of the year; NA rows skipped (37 of 153).",
  "Source: R datasets::airquality (New York State Department of Conservation)."),
  "day_of_year", "ozone_ppb", as.numeric(as.Date(sprintf("1973-%02d-%02d", aq$Month, aq$Day))
                                       - as.Date("1972-12-31")), aq$Ozone)
w("sunspot_year.csv", c("Yearly mean relative sunspot numbers, 1700-1988 (zeros occur).",
  "Source: R datasets::sunspot.year (Tong 1996; SIDC)."),
  "year", "sunspots", tx(sunspot.year), as.numeric(sunspot.year))
w("lake_huron.csv", c("Annual level of Lake Huron (ft), 1875-1972.",
  "Source: R datasets::LakeHuron (Brockwell and Davis 1991)."),
  "year", "level_ft", tx(LakeHuron), as.numeric(LakeHuron))
w("lynx.csv", c("Annual number of lynx trapped in the Mackenzie River district, Canada, 1821-1934.",
  "Source: R datasets::lynx (Campbell and Walker 1977)."),
  "year", "lynx", tx(lynx), as.numeric(lynx))
w("nhtemp.csv", c("Mean annual temperature (deg F) in New Haven, Connecticut, 1912-1971.",
  "Source: R datasets::nhtemp (Vaux 1972)."),
  "year", "temp_F", tx(nhtemp), as.numeric(nhtemp))
w("presidents.csv", c("Quarterly approval rating (percent) of the US president, 1945-1974;",
  "NA quarters skipped (6 of 120).  Source: R datasets::presidents (Gallup)."),
  "year", "approval_percent", tx(presidents), as.numeric(presidents))
w("co2.csv", c("Monthly atmospheric CO2 concentration (ppm) at Mauna Loa, 1959-1997.",
  "Source: R datasets::co2 (Keeling and Whorf, Scripps)."),
  "year", "co2_ppm", tx(co2), as.numeric(co2))
w("discoveries.csv", c("Number of great inventions and scientific discoveries per year, 1860-1959",
  "(zeros occur).  Source: R datasets::discoveries (World Almanac 1975)."),
  "year", "discoveries", tx(discoveries), as.numeric(discoveries))
w("wwwusage.csv", c("Number of users connected to the Internet through a server, per minute, 100 minutes.",
  "Source: R datasets::WWWusage (Durbin and Koopman 2001)."),
  "minute", "users", tx(WWWusage), as.numeric(WWWusage))
w("uspop.csv", c("Population of the United States (millions), census every 10 years, 1790-1970.",
  "Source: R datasets::uspop (US Census)."),
  "year", "millions", tx(uspop), as.numeric(uspop))
b <- MASS::beav1
w("beaver_temperature.csv", c("Body temperature (deg C) of a female beaver every 10 minutes (one gap),",
  "x = minutes since midnight of day 346.  Source: R MASS::beav1 (Reynolds 1994)."),
  "minute", "temp_C", (b$day - 346) * 1440 + (b$time %/% 100) * 60 + b$time %% 100, b$temp)
m <- boot::manaus
w("manaus.csv", c("Monthly mean height (m, relative to a reference) of the Rio Negro at Manaus, 1903-1992.",
  "Source: R boot::manaus (Sternberg 1987)."),
  "year", "height_m", tx(m), as.numeric(m))
