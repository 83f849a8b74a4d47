#!/usr/bin/env python3
"""Drives the monitor's page in a real headless chromium (Selenium and
Debian's chromium-driver), as a user would: opens a thumbnail, clicks a
pixel of the whole frame and waits for the pixel inspector.  Every
thumbnail's picture must load first.

Usage: monitor_click.py URL SCREENSHOT.png X_SHARE Y_SHARE
Prints "FRAME I,J POINTS" (the frame opened, the pixel the page asked for,
the points of the ray's path it drew) and the report's first line; keeps a
screenshot.  Exits non-zero if any step does not happen within 30 s.
"""
import sys

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

url, screenshot, x_share, y_share = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
options = webdriver.ChromeOptions()
for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1400,900"):
    options.add_argument(arg)
driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
try:
    driver.get(url)
    wait = WebDriverWait(driver, 30)
    thumbnail = wait.until(lambda d: d.find_element(By.CSS_SELECTOR, "figure[data-frame]"))
    # Every thumbnail's picture has loaded (a broken one has no natural width).
    thumbs_loaded = ("const t = [...document.querySelectorAll('figure[data-frame] img')];"
                     "return t.length > 0 && t.every(i => i.complete && i.naturalWidth > 0)")
    wait.until(lambda d: d.execute_script(thumbs_loaded))
    frame = thumbnail.get_attribute("data-frame")
    thumbnail.click()
    loaded = "const i = document.getElementById('big'); return i.complete && i.naturalWidth > 0"
    big = wait.until(lambda d: d.find_element(By.ID, "big") if d.execute_script(loaded) else None)
    width, height = big.size["width"], big.size["height"]
    # Selenium 4 offsets are from the element's centre.
    ActionChains(driver).move_to_element_with_offset(
        big, int(width * (x_share - 0.5)), int(height * (y_share - 0.5))).click().perform()
    report = wait.until(lambda d: d.find_element(By.ID, "trace-report")
                        if d.find_element(By.ID, "trace-report").get_attribute("data-pixel") else None)
    points = driver.find_element(By.ID, "trace-path").get_attribute("data-points")
    driver.save_screenshot(screenshot)
    print(frame, report.get_attribute("data-pixel"), points)
    print(report.text.splitlines()[0])
finally:
    driver.quit()
